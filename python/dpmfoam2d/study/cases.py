# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The cases of a dpmStudy directory, read for results/: each case's
settings, variant and seed, and its summary row (M, the segregation indices
and the bed statistics over the last X s, Umf and U0 from its log)."""

import os
import re
from collections import OrderedDict

import numpy as np

from ..bed_statistics import write_bed_statistics
from ..fields import FieldError
from ..tables import read_postprocessing

# Columns of dpmBedStatistics' tables that the summary averages
BED_STATISTICS = ("bedHeight", "bubbleFraction", "emulsionVoidage", "speedRmsSmall",
                  "speedRmsLarge", "stillSmall", "stillLarge", "voidageSmall",
                  "voidageLarge")
INDICES = ("vertical", "horizontal", "hSmall", "hLarge", "rSmall", "rLarge")

BASELINE = "baseline"       # the template as it is (no variant)


def say(*args):
    print(*args, flush=True)


def flat_dictionary(path):
    """Entries of a flat OpenFOAM dictionary (caseSettings): name -> text."""
    out = {}
    with open(path) as f:
        text = re.sub(r"//[^\n]*", "", f.read())
    for m in re.finditer(r"^\s*([A-Za-z]\w*)\s+([^;{}]+);", text, re.M):
        out[m.group(1)] = m.group(2).strip()
    return out


def find_cases(study_dir):
    """Every case of the study directory: dicts with dir, case, wSmall,
    pressure, seed (None: the template's, no suffix) and variant."""
    cases = []
    for name in sorted(os.listdir(study_dir)):
        d = os.path.join(study_dir, name)
        settings = os.path.join(d, "constant", "caseSettings")
        # a dot name: a case being made (runner.make_dir), not yet one
        if name in ("beds", "results") or name.startswith(".") or not os.path.isfile(settings):
            continue
        s = flat_dictionary(settings)
        if "pressure" not in s or "wSmall" not in s:
            continue
        record = os.path.join(d, "constant", "variant")
        variant = BASELINE
        if os.path.isfile(record):
            with open(record) as f:
                m = re.match(r"# variant (\S+)", f.readline())
            variant = m.group(1) if m else name
        seeded = re.search(r"_seed(\d+)$", name) is not None
        p = float(s["pressure"])
        cases.append({"dir": d, "case": name, "variant": variant,
                      "wSmall": float(s["wSmall"]), "pressure": int(p) if p == int(p) else p,
                      "seed": int(float(s["seed"])) if seeded and "seed" in s else None,
                      "endTime": float(s["endTime"]) if "endTime" in s else None})
    cases.sort(key=lambda c: (c["variant"] != BASELINE, c["variant"], c["wSmall"],
                              c["pressure"], c["seed"] or 0))
    return cases


def time_windows(t, M, tS, S, X):
    """Means of M and of the vertical and horizontal indices over the
    complete windows (k X, (k+1) X], k = 0, 1, ... of one case's tables."""
    def within(times, t0, t1):
        return (times > t0 + 1e-9) & (times <= t1 + 1e-9)

    out, k = [], 0
    while (k + 1) * X <= t[-1] + 1e-9:
        t0, t1 = k * X, (k + 1) * X
        inM, inS = within(t, t0, t1), within(tS, t0, t1)
        if inM.any() and inS.any():
            out.append({"tStart": round(t0, 9), "tEnd": round(t1, 9), "M": M[inM].mean(),
                        "vertical": S["vertical"][inS].mean(),
                        "horizontal": S["horizontal"][inS].mean()})
        k += 1
    return out


def case_row(c, X, rate_window):
    """One case's summary row and its windows, or (None, None) without data."""
    case = c["dir"]
    M = read_postprocessing(case, "laceyIndex", "laceyIndex.dat")
    S = read_postprocessing(case, "laceyIndex", "segregation.dat")
    if M is None or S is None or len(M["Time"]) == 0:
        say("results: no laceyIndex data in %s" % case)
        return None, None
    t = M["Time"]
    last = t >= t[-1] - X - 1e-9
    tS = S["Time"]
    lastS = tS >= tS[-1] - X - 1e-9
    t0, t1 = rate_window or (0.0, X)
    inRate = (t > t0 + 1e-9) & (t <= t1 + 1e-9)
    row = OrderedDict(case=c["case"], variant=c["variant"], seed=c["seed"] or "",
                      wSmall=c["wSmall"], pressure=c["pressure"], Umf=np.nan, U0=np.nan,
                      time=t[-1], finished=c["endTime"] is None or t[-1] >= c["endTime"] - 1e-6,
                      M0=M["M"][0], Mfinal=M["M"][-1], Mmean=M["M"][last].mean(),
                      Mrate=(M["M"][inRate] / M["M"][0]).mean()
                      if inRate.any() and M["M"][0] > 0 and t[-1] >= t1 - 1e-9 else np.nan)
    for k in INDICES:
        row[k] = S[k][lastS].mean()
    # Lacey's own N (one sample), when the case has it
    L = read_postprocessing(case, "laceyIndexPerSample", "laceyIndex.dat")
    row["MsampleFinal"] = L["M"][-1] if L is not None and len(L["M"]) else np.nan
    row["MsampleMean"] = L["M"][L["Time"] >= L["Time"][-1] - X - 1e-9].mean() \
        if L is not None and len(L["M"]) else np.nan
    if not os.path.isfile(os.path.join(case, "constant", "archivedCase")):
        remake_bed_statistics(case)
    row.update(bed_statistics(case, X))
    windows = [OrderedDict(case=c["case"], variant=c["variant"], seed=c["seed"] or "",
                           wSmall=c["wSmall"], pressure=c["pressure"], **win)
               for win in time_windows(t, M["M"], tS, S, X)]
    for name in sorted(f for f in os.listdir(case) if f.startswith("log.dpmFoam2D")):
        with open(os.path.join(case, name), errors="replace") as f:
            m = re.search(r"Umf \(Wen-Yu\) (\S+) m/s, U0/Umf \S+, (?:U0 - Umf \S+ m/s, )?"
                          r"U0 (\S+) m/s", f.read())
        if m:
            row["Umf"], row["U0"] = float(m.group(1)), float(m.group(2))
            break
    return row, windows


def remake_bed_statistics(case):
    """The case's bed statistics (dpmBedStatistics' tables) made anew from
    its fields and particle files; a case without them is said, not fatal
    (a summary of a run elsewhere has only the tables, and keeps them)."""
    try:
        write_bed_statistics(case)
    except (FieldError, ValueError) as e:
        say("results: dpmBedStatistics: %s" % e)


def bed_statistics(case, X):
    """Means over the last X s of dpmBedStatistics' tables."""
    out = {k: np.nan for k in BED_STATISTICS}
    for name in ("bed.dat", "particles.dat"):
        T = read_postprocessing(case, "bedStatistics", name)
        if T is None or not len(T["Time"]):
            continue
        last = T["Time"] >= T["Time"][-1] - X - 1e-9
        for k in BED_STATISTICS:
            if k in T:
                out[k] = np.nanmean(T[k][last]) if np.isfinite(T[k][last]).any() \
                    else np.nan
    return out
