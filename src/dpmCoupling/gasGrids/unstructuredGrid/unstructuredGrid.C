/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
\*---------------------------------------------------------------------------*/

#include "unstructuredGrid.H"
#include "OStringStream.H"
#include "Time.H"
#include "addToRunTimeSelectionTable.H"
#include "knownEntries.H"
#include "positiveEntry.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(unstructuredGrid, 0);
    addToRunTimeSelectionTable(gasGrid, unstructuredGrid, mesh);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::label Foam::unstructuredGrid::quadratureEntry
(
    const dictionary& dict,
    const word& name,
    const label deflt,
    const label lower,
    const label upper,
    const label multipleOf
)
{
    const dictionary* coeffs =
        dict.findDict("unstructuredCoeffs", keyType::LITERAL);
    if (!coeffs) return deflt;
    const string where("constant/particleProperties/unstructuredCoeffs");
    checkKnownEntries
    (
        *coeffs, wordList{"quadratureShells", "quadratureDirections"}, where
    );
    const label n = coeffs->lookupOrDefault<label>(name, deflt);
    checkedRange(*coeffs, name, n, lower, upper, false);
    if (n % multipleOf)
    {
        FatalIOErrorInFunction(*coeffs)
            << "Entry '" << name << "' = " << n << " in " << where.c_str()
            << " is not a multiple of " << multipleOf << exit(FatalIOError);
    }
    return n;
}


void Foam::unstructuredGrid::checkResolvedInDepth() const
{
    // Empty front and back patches, or one layer of cells each spanning
    // the whole depth (walls in front and behind)
    bool oneCellThick = mesh_.nGeometricD() != 3;
    if (!oneCellThick)
    {
        const pointField& points = mesh_.points();
        oneCellThick = true;
        forAll(mesh_.cells(), celli)
        {
            const boundBox cellBb(points, mesh_.cellPoints()[celli], false);
            if (cellBb.span().z() < (1 - 1e-6)*depth_)
            {
                oneCellThick = false;
                break;
            }
        }
    }
    if (oneCellThick)
    {
        FatalErrorInFunction
            << "gasGrid unstructured resolves the gas in 3D, but the mesh of "
            << mesh_.time().path() << " is one cell thick in z ("
            << mesh_.nCells() << " cells, each through the whole depth "
            << depth_ << " m)" << nl
            << "    Use gasGrid cartesian for a bed one cell thick (voidage"
            << " models discs2D and slab3D), or a mesh with cells through"
            << " the depth for gasGrid unstructured (voidageModel spheres3D)."
            << exit(FatalError);
    }
}


void Foam::unstructuredGrid::measureCells()
{
    const scalarField& V = mesh_.V();
    const vectorField& Sf = mesh_.faceAreas();
    const cellList& cells = mesh_.cells();

    minWidth_ = GREAT;
    maxWidth_ = 0;
    forAll(cells, celli)
    {
        scalar largestFace = 0;
        for (const label facei : cells[celli])
        {
            largestFace = max(largestFace, mag(Sf[facei]));
        }
        const scalar width = V[celli]/largestFace;
        minWidth_ = min(minWidth_, width);
        maxWidth_ = max(maxWidth_, width);
    }

    faceNormals_ = Sf/mag(Sf);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::unstructuredGrid::unstructuredGrid(const fvMesh& mesh)
:
    unstructuredGrid(mesh, defaultShells, defaultDirections)
{}


Foam::unstructuredGrid::unstructuredGrid
(
    const dictionary& dict,
    const fvMesh& mesh
)
:
    unstructuredGrid
    (
        mesh,
        quadratureEntry(dict, "quadratureShells", defaultShells, 1, 256, 1),
        quadratureEntry
        (
            dict, "quadratureDirections", defaultDirections, 2, 4096, 2
        )
    )
{}


Foam::unstructuredGrid::unstructuredGrid
(
    const fvMesh& mesh,
    const label nShells,
    const label nDirections
)
:
    gasGrid(mesh),
    depth_(mesh.bounds().span().z()),
    minWidth_(0),
    maxWidth_(0),
    nInexactPoints_(0),
    stencilStride_(0)
{
    checkResolvedInDepth();

    // The mesh's demand-driven data, made here once: the threads below
    // only read it
    (void)mesh.cellCentres();
    (void)mesh.faceCentres();
    (void)mesh.cellPoints();
    (void)mesh.pointCells();
    (void)mesh.cellCells();
    (void)mesh.tetBasePtIs();
    (void)mesh.cellTree();

    measureCells();
    makePointWeights();
    makeQuadrature(nShells, nDirections);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::scalarField& Foam::unstructuredGrid::cellAreas() const
{
    FatalErrorInFunction
        << "gasGrid unstructured resolves the gas in 3D: its cells have no"
        << " area in the x-y plane (a grid one cell thick, gasGrid cartesian,"
        << " has)" << abort(FatalError);
    return mesh_.V();
}


void Foam::unstructuredGrid::discShares
(
    const label, const double*, const double*, const double*, const label,
    cellWeights&
) const
{
    FatalErrorInFunction
        << "gasGrid unstructured resolves the gas in 3D: voidageModel"
        << " discs2D needs a gas grid one cell thick (gasGrid cartesian with"
        << " nz 1); use voidageModel spheres3D" << exit(FatalError);
}


void Foam::unstructuredGrid::sphereColumnShares
(
    const label, const double*, const double*, const double*, const label,
    cellWeights&
) const
{
    FatalErrorInFunction
        << "gasGrid unstructured resolves the gas in 3D: voidageModel"
        << " slab3D needs a gas grid one cell thick (gasGrid cartesian with"
        << " nz 1), each cell a column through the depth; use voidageModel"
        << " spheres3D" << exit(FatalError);
}


Foam::scalar Foam::unstructuredGrid::largestSpreadingDiameter() const
{
    // Not a limit of the quadrature (it shares a sphere over any cells) but
    // of its resolution: a sphere six cells across leaves about 27 of the
    // 3072 points to a cell's volume. The same bound as cartesianGrid's,
    // so that a case's spreadingDiameter holds on either grid
    return 6*minWidth_;
}


Foam::string Foam::unstructuredGrid::cellSize() const
{
    OStringStream os;
    os  << minWidth_ << " to " << maxWidth_ << " wide";
    return os.str();
}


Foam::string Foam::unstructuredGrid::cellCounts() const
{
    OStringStream os;
    os  << mesh_.nCells() << " (unstructured)";
    return os.str();
}


void Foam::unstructuredGrid::report(Ostream& os) const
{
    os  << "    gas mesh " << mesh_.nCells() << " cells (unstructured, "
        << "resolved in 3D), " << depth_*1e3 << " mm deep, cells "
        << minWidth_*1e3 << " to " << maxWidth_*1e3 << " mm wide (volume /"
        << " largest face), shares of a sphere by " << quadrature_.size()
        << " points" << nl
        << "    mesh points whose cells' centres do not surround them (a"
        << " linear field inexact beside them): " << nInexactPoints_ << nl;
}


// ************************************************************************* //
