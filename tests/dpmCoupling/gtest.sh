#!/bin/bash
# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs one of the coupling's GoogleTest applications in the project's
# environment (so that ctest works from any shell); its exit status is the
# tests'.
#   gtest.sh <application> [-case <dir>] [--gtest_filter=Suite.Name]
. "$(dirname "${BASH_SOURCE[0]}")/../../etc/bashrc" || exit 1
app="${1:?usage: $0 <application> [arguments]}"
shift
exec "$DPMFOAM2D_BUILD/tests/bin/$app" "$@"
