# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The study runner (dpmStudy): cases made from a template over the matrix
its study file defines, run here or on Slurm, and summed up in results/."""
