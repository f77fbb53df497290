# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The study's merge of studies (import) and its results on summary cases of
known tables, and dpmStudy's command line: one subcommand per thing it does,
each refusing what does not belong to it."""

import os
import shutil

import pytest

from dpmfoam2d import project, tables
from dpmfoam2d.study import archive, command_line, results
from conftest import study_dir, summary_case


def quiet(_):
    pass


def test_import_merges_and_sums_up(tmp_path):
    # Seed 1 in A (final M 0.5), seed 2 in B (0.7): after B's import A holds
    # both. M's mean over the last 0.02 s, the rows at 0.03, 0.04 and 0.05 s
    # of M rising linearly to its final value at 0.05 s, is 0.8 of it: 0.40
    # and 0.56; their mean 0.48, s = 0.16/sqrt(2), and the half-width
    # t(0.975; 1) s/sqrt(2) = 12.706 x 0.08
    a = study_dir(str(tmp_path / "A"), ("w0.50_1bar_seed1", 1, 0.5))
    b = study_dir(str(tmp_path / "B"), ("w0.50_1bar_seed2", 2, 0.7))
    assert archive.import_study(a, b, quiet) == 1
    assert archive.is_summary(os.path.join(a, "w0.50_1bar_seed2"))
    results.results(a, 0.02, None, False, results.definition_of(a, None))
    E = tables.study_table(a, "ensemble")
    assert E["n"].tolist() == [2] and E["seeds"].tolist() == ["1 2"]
    assert E["Mmean"] == pytest.approx([0.48])
    assert E["MmeanCI"] == pytest.approx([12.706 * 0.08], abs=1e-3)
    # imported again: the case is there with the same settings, kept
    said = []
    assert archive.import_study(a, b, said.append) == 0
    assert said == ["import: w0.50_1bar_seed2 is here already, with the same settings: kept"]


def test_import_refuses_other_settings(tmp_path):
    a = study_dir(str(tmp_path / "A"), ("w0.50_1bar_seed1", 1, 0.5))
    b = study_dir(str(tmp_path / "B"))
    summary_case(b, "w0.50_1bar_seed2", 2, 0.7, end_time=0.04)
    with pytest.raises(archive.ArchiveError,
                       match="its settings differ from w0.50_1bar_seed1's: endTime 0.05 here, "
                             "0.04 there"):
        archive.import_study(a, b, quiet)
    shutil.rmtree(os.path.join(b, "w0.50_1bar_seed2"))
    summary_case(b, "w0.50_1bar_seed2", 2, 0.7, gas="viscosity 1.9e-05;")
    with pytest.raises(archive.ArchiveError, match="its dictionaries differ .*gasProperties"):
        archive.import_study(a, b, quiet)
    assert sorted(os.listdir(a)) == ["studyDict", "w0.50_1bar_seed1"]     # left as it was


def run_command(args, capsys):
    """dpmStudy's exit and what it said on stderr."""
    with pytest.raises(SystemExit) as e:
        command_line.main(args)
    return e.value.code, capsys.readouterr().err


def test_subcommands_take_their_own_options(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, err = run_command(["run", "s", "-j", "0"], capsys)
    assert code == 2 and "dpmStudy run: error: -j 0: cases at once must be >= 1" in err
    code, err = run_command(["submit", "s", "-j", "2"], capsys)
    assert code == 2 and "unrecognized arguments: -j 2" in err
    code, err = run_command(["status", "s", "-w", "0.5"], capsys)
    assert code == 2 and "unrecognized arguments: -w 0.5" in err
    code, err = run_command(["results", "s", "--", "--partition=short"], capsys)
    assert code == 2 and "options after -- are for sbatch: dpmStudy submit" in err
    code, err = run_command(["results", "nothing"], capsys)
    assert code == 2 and "dpmStudy results: error: no study directory nothing" in err
    # the old form, a directory where the command goes, names the commands
    code, err = run_command(["run/paperStudy", "-w", "0.5"], capsys)
    assert code == 2 and "invalid choice: 'run/paperStudy'" in err and "'submit'" in err
    assert not os.listdir(tmp_path)                     # nothing made


def test_template_from_the_environment(tmp_path, monkeypatch, capsys):
    # without -template the project's tutorials/paperStudy, found through
    # DPMFOAM2D_PROJECT; without it, the refusal names the variable
    monkeypatch.delenv(project.VARIABLE, raising=False)
    with pytest.raises(project.ProjectError, match="DPMFOAM2D_PROJECT is not set"):
        command_line.main(["variants"])
    template = tmp_path / "tutorials" / "paperStudy"
    (template / "variants").mkdir(parents=True)
    (template / "variants" / "upwind").write_text("# upwind for the gas's momentum\n")
    monkeypatch.setenv(project.VARIABLE, str(tmp_path))
    command_line.main(["variants"])
    assert capsys.readouterr().out.split() == ["upwind", "upwind", "for", "the", "gas's",
                                               "momentum"]
