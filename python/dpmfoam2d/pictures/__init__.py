# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Pictures of a case: snapshots and movies rendered by ParaView off-screen,
M(t) plots, ParaView opened on a case."""
