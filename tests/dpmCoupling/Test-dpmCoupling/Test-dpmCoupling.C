/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
-------------------------------------------------------------------------------
Application
    Test-dpmCoupling

Description
    Checks of the coupling library against numbers from outside the code:
    circle geometry, the Hoomans voidage of close packings, Wen-Yu's Umf of
    the paper's Table 3, Stokes' law, the Ergun equation and the Dallavalle
    drag of a single sphere; the unknown-entry check (knownEntries.H); the
    closures for mixtures (GidaspowBlend, KochHill, Beetstra) against their
    limits and against values worked by hand from the published formulas;
    the Sauter mean diameter of mapped mixtures; the voidage models (their
    selection, the mapped volumes against the particles' volume, lattices
    of known solid fraction). GoogleTest cases, run in a case with the
    paper's 20 x 120 mesh (2.5 mm thick):

        Test-dpmCoupling -case <dir> [--gtest_filter=Suite.Name]

\*---------------------------------------------------------------------------*/

#include "couplingTestMain.H"

int main(int argc, char *argv[])
{
    return couplingTest::main(argc, argv, couplingTest::readCase);
}


// ************************************************************************* //
