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
    foamApiVersion

Description
    Smoke test of the development kit: a trivial application compiled by
    wmake against Debian's OpenFOAM libraries. Prints the API version that
    the libraries report, so a header/library mismatch shows at once.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "foamVersion.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::noBanner();
    argList::noParallel();
    #include "setRootCase.H"

    Info<< "api " << foamVersion::api << nl
        << "patch " << foamVersion::patch.c_str() << nl
        << "label bytes " << sizeof(label) << nl
        << "scalar bytes " << sizeof(scalar) << endl;

    return 0;
}
