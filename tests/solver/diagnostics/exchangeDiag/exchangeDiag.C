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
Class
    Foam::functionObjects::exchangeDiag

Description
    Diagnostic, not part of the build: prints every gas step the vertical
    force the particles felt, summed over the cells (Fp V), and the implicit
    part of the exchange that only the gas sees (Kc (U - U*) V):

        exchangeDiag <time> <sum Fp_y V> <sum Kc (U_y - U*_y) V>

    With the particles' momentum from the saved states it gives the walls'
    share of the weight exactly (docs/model.md, DiFelice). Build and use:

        cd tests/solver/diagnostics/exchangeDiag && wmake libso
        functions { exchange { type exchangeDiag; libs ("libexchangeDiag.so"); } }

    Reads the registered fields Kc, Ustar and Fp of dpmCloud.

\*---------------------------------------------------------------------------*/

#include "fvMeshFunctionObject.H"
#include "volFields.H"
#include "addToRunTimeSelectionTable.H"

namespace Foam
{
namespace functionObjects
{

class exchangeDiag
:
    public fvMeshFunctionObject
{
public:

    TypeName("exchangeDiag");

    exchangeDiag(const word& name, const Time& runTime, const dictionary& dict)
    :
        fvMeshFunctionObject(name, runTime, dict)
    {}

    bool execute()
    {
        if (!mesh_.foundObject<volScalarField>("Kc")) return true;

        const volScalarField& Kc = mesh_.lookupObject<volScalarField>("Kc");
        const volVectorField& Us = mesh_.lookupObject<volVectorField>("Ustar");
        const volVectorField& Fp = mesh_.lookupObject<volVectorField>("Fp");
        const volVectorField& U = mesh_.lookupObject<volVectorField>("U");
        const scalarField& V = mesh_.V();

        const vector implicitPart =
            gSum(Kc.primitiveField()*(U.primitiveField() - Us.primitiveField())*V);
        const vector felt = gSum(Fp.primitiveField()*V);

        Info<< "exchangeDiag " << mesh_.time().value() << " " << felt.y()
            << " " << implicitPart.y() << endl;
        return true;
    }

    bool write() { return true; }
};

defineTypeNameAndDebug(exchangeDiag, 0);
addToRunTimeSelectionTable(functionObject, exchangeDiag, dictionary);

} // End namespace functionObjects
} // End namespace Foam
