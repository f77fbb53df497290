# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""results/verdicts.md of a dpmStudy directory: what each variant does to
the paper's findings 2-4, judged against the baseline's seeds.

For every contrast of findings.md that a variant and the baseline both
have: the variant's value, its shift from the baseline's with an interval
(ensemble.shift_ci: a one-seed variant case takes the baseline's
scatter of the same case), and the effect: turns the finding round (its
sign becomes the paper's where the baseline's is the reverse), moves it
toward or away from the paper beyond the packings' scatter, or leaves it
within that scatter. Then, per finding, the variants under each effect:
the table the verdicts of docs/reproduction.md rest on."""

import os
from collections import OrderedDict

from . import ensemble as ens
from ..files import replacing


def opposite(sign):
    return {"+": "-", "-": "+"}.get(sign, sign)


def effect(paper, base_sign, var_sign, shift_sign):
    """The variant's effect on one contrast, from the signs (as
    ensemble.sign_of gives them) of the baseline's contrast, the
    variant's and the shift between them. A one-seed sign counts only
    where the shift leaves the baseline's scatter."""
    one_seed = var_sign.endswith("?")
    confirm = " (one seed: to confirm over seeds)" if one_seed else ""
    vs = var_sign.rstrip("?")
    if one_seed and shift_sign not in ("+", "-"):
        vs = "none"     # one run's sign within the baseline's scatter says nothing
    if base_sign == opposite(paper) and vs == paper:
        return "turns it round" + confirm
    if base_sign == paper and vs == opposite(paper):
        return "turns it against the paper" + confirm
    if base_sign == "none" and var_sign in ("+", "-"):   # resolved over seeds only
        return "gives the paper's sign" if vs == paper else "gives the reverse"
    if shift_sign in ("+", "-"):
        return "moves it %s the paper, sign kept" % (
            "toward" if shift_sign == paper else "away from")
    if shift_sign == "none":
        return "within the packings' scatter"
    return "no interval (the baseline needs two seeds or more)"


def variant_effects(found, groups, baseline_name):
    """Rows of verdicts.md/csv. found: findings() rows; groups: (variant,
    w, p) -> the finished rows of its seeds; each finding row carries its
    cases in 'cases' (a, b or None) and its quantity; baseline_name: the
    variant name of the template as it is."""
    base = {(r["finding"], r["comparison"]): r for r in found if r["variant"] == baseline_name}
    out = []
    for r in found:
        b = base.get((r["finding"], r["comparison"]))
        if r["variant"] == baseline_name or b is None:
            continue
        k = r["quantity"]
        keys = [c for c in r["cases"] if c is not None]
        variant = [[x[k] for x in groups[(r["variant"],) + c]] for c in keys]
        baseline = [[x[k] for x in groups[(baseline_name,) + c]] for c in keys]
        shift, half, borrowed = ens.shift_ci(variant, baseline)
        shift_sign = ens.sign_of(shift, half)
        out.append(OrderedDict(
            finding=r["finding"], comparison=r["comparison"], paperSign=r["paperSign"],
            variant=r["variant"], nVariant=r["nA"], baselineValue=b["difference"],
            baselineCI=b["CI"], baselineSign=b["sign"], value=r["difference"],
            CI=r["CI"], sign=r["sign"], shift=shift, shiftCI=half,
            borrowed=borrowed, shiftSign=shift_sign,
            effect=effect(r["paperSign"], b["sign"], r["sign"], shift_sign)))
    return out


def write_verdicts(out, effects, level):
    """verdicts.md in the results directory `out`."""
    lvl = int(round(level * 100))
    with replacing(os.path.join(out, "verdicts.md")) as f:
        f.write("What each variant does to the paper's findings, against the baseline's "
                "seeds. value: the variant's contrast (findings.md); shift: the variant's "
                "contrast minus the baseline's, +- its %d %% interval (Welch-Satterthwaite; "
                "* where a variant case has one seed and takes the scatter of the "
                "baseline's seeds of the same case, a prediction interval for one run). "
                "A finding is turned round where the variant's sign is the paper's and "
                "the baseline's the reverse; a one-seed sign is a screening result.\n\n"
                % lvl)
        if not effects:
            f.write("No variant shares a contrast with the baseline yet.\n")
            return
        by_finding = OrderedDict()
        for e in effects:
            by_finding.setdefault((e["finding"], e["comparison"], e["paperSign"],
                                   ens.fmt(e["baselineValue"], e["baselineCI"])),
                                  OrderedDict()).setdefault(
                e["effect"].split(" (")[0], []).append(
                    e["variant"] + ("?" if e["sign"].endswith("?") else ""))
        f.write("| finding | comparison | paper | baseline | effect | variants |\n")
        f.write("|" + "---|" * 6 + "\n")
        for (finding, what, paper, baseline), kinds in by_finding.items():
            for kind, names in kinds.items():
                f.write("| %s | %s | %s | %s | %s | %s |\n" % (
                    finding, what, paper, baseline, kind, ", ".join(names)))
        f.write("\n(? after a name: one seed, a sign without an interval.)\n\n")
        f.write("| finding | comparison | variant | seeds | value | shift | effect |\n")
        f.write("|" + "---|" * 7 + "\n")
        for e in effects:
            f.write("| %s | %s | %s | %d | %s | %s%s | %s |\n" % (
                e["finding"], e["comparison"], e["variant"], e["nVariant"],
                ens.fmt(e["value"], e["CI"]), ens.fmt(e["shift"], e["shiftCI"]),
                " *" if e["borrowed"] else "", e["effect"]))
