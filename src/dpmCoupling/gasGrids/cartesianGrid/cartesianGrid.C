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

#include "cartesianGrid.H"
#include "volFields.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(cartesianGrid, 0);
    addToRunTimeSelectionTable(gasGrid, cartesianGrid, mesh);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cartesianGrid::cartesianGrid(const fvMesh& mesh)
:
    gasGrid(mesh),
    x0_(0), y0_(0), z0_(0),
    dx_(0), dy_(0), dz_(0), depth_(0),
    nx_(0), ny_(0), nz_(0)
{
    // One cell thick (front and back empty), or resolved in all three
    const Vector<label>& geomD = mesh.geometricD();
    const bool oneCellThick = mesh.nGeometricD() == 2 && geomD.z() == -1;
    if (!oneCellThick && mesh.nGeometricD() != 3)
    {
        FatalErrorInFunction
            << "The mesh of " << mesh.time().path()
            << " is neither one cell thick in z nor resolved in 3D" << nl
            << "    dpmFoam2D needs the bed in the x-y plane: one cell thick"
            << " with the front and back patches of type empty (blockMesh:"
            << " n = (nx ny 1)), or nz cells deep with walls in front and"
            << " behind (n = (nx ny nz))." << exit(FatalError);
    }

    const boundBox& bb = mesh.bounds();
    x0_ = bb.min().x();
    y0_ = bb.min().y();
    z0_ = bb.min().z();
    depth_ = bb.span().z();

    // Every cell must be an axis-aligned box of the same size
    const pointField& points = mesh.points();
    const scalar tol = 1e-6;
    forAll(mesh.cells(), celli)
    {
        const boundBox cellBb(points, mesh.cellPoints(celli), false);
        const vector span = cellBb.span();
        if (celli == 0)
        {
            dx_ = span.x();
            dy_ = span.y();
            dz_ = oneCellThick ? depth_ : span.z();
        }
        if (oneCellThick && span.z() < (1 - tol)*depth_)
        {
            FatalErrorInFunction
                << "The mesh of " << mesh.time().path()
                << " is not one cell thick in z: cell " << celli
                << " is " << span.z() << " m thick, the mesh " << depth_
                << " m" << nl
                << "    dpmFoam2D needs the front and back patches of type"
                << " empty on a mesh one cell thick (blockMesh: n ="
                << " (nx ny 1)), or walls there on a mesh nz cells deep."
                << exit(FatalError);
        }
        const bool sameSize =
            mag(span.x() - dx_) < tol*dx_ && mag(span.y() - dy_) < tol*dy_
         && mag(span.z() - dz_) < tol*dz_;
        const bool isBox =
            mag(mesh.V()[celli] - span.x()*span.y()*span.z())
          < tol*mesh.V()[celli];
        if (!sameSize || !isBox)
        {
            FatalErrorInFunction
                << "The mesh of " << mesh.time().path()
                << " is not a uniform Cartesian grid: cell " << celli
                << " at " << mesh.C()[celli] << " is " << span.x() << " x "
                << span.y() << " x " << span.z() << " m, the first cell "
                << dx_ << " x " << dy_ << " x " << dz_ << " m" << nl
                << "    dpmFoam2D needs equal box-shaped cells"
                << " (blockMesh with simpleGrading (1 1 1))."
                << exit(FatalError);
        }
    }

    nx_ = label(std::round(bb.span().x()/dx_));
    ny_ = label(std::round(bb.span().y()/dy_));
    nz_ = oneCellThick ? 1 : label(std::round(depth_/dz_));
    const bool enough = nx_ >= 2 && ny_ >= 2 && (oneCellThick || nz_ >= 2);
    if (!enough || nx_*ny_*nz_ != mesh.nCells())
    {
        FatalErrorInFunction
            << "The mesh of " << mesh.time().path() << " has "
            << mesh.nCells() << " cells but its bounding box holds "
            << nx_ << " x " << ny_ << " x " << nz_ << " cells of " << dx_
            << " x " << dy_ << " x " << dz_ << " m; dpmFoam2D needs a full"
            << " box-shaped grid of at least 2 x 2 cells (x 2 when resolved"
            << " in depth)" << exit(FatalError);
    }

    cellOfIJK_.setSize(nx_*ny_*nz_, -1);
    forAll(mesh.C(), celli)
    {
        const point& c = mesh.C()[celli];
        const label i = label(std::floor((c.x() - x0_)/dx_));
        const label j = label(std::floor((c.y() - y0_)/dy_));
        const label k = oneCellThick ? 0 : label(std::floor((c.z() - z0_)/dz_));
        cellOfIJK_[i + nx_*(j + ny_*k)] = celli;
    }
    if (findIndex(cellOfIJK_, -1) != -1)
    {
        FatalErrorInFunction
            << "The cells of " << mesh.time().path()
            << " do not fill a box-shaped grid" << exit(FatalError);
    }

    bounds_ = boundBox
    (
        point(x0_, y0_, z0_),
        point(x0_ + nx_*dx_, y0_ + ny_*dy_, z0_ + depth_)
    );
    cellVolumes_.setSize(mesh.nCells(), dx_*dy_*dz_);
    cellAreas_.setSize(mesh.nCells(), dx_*dy_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::string Foam::cartesianGrid::cellSize() const
{
    OStringStream os;
    os  << dx_ << " x " << dy_;
    if (resolvedInDepth())
    {
        os  << " x " << dz_;
    }
    return os.str();
}


Foam::string Foam::cartesianGrid::cellCounts() const
{
    OStringStream os;
    os  << nx_ << " x " << ny_ << " x " << nz_;
    return os.str();
}


void Foam::cartesianGrid::report(Ostream& os) const
{
    os  << "    bed depth (mesh thickness) " << depth_*1e3 << " mm, gas cells "
        << dx_*1e3 << " x " << dy_*1e3;
    if (resolvedInDepth())
    {
        os  << " x " << dz_*1e3 << " mm (" << nx_ << " x " << ny_ << " x "
            << nz_ << ")" << nl;
    }
    else
    {
        os  << " mm (" << nx_ << " x " << ny_ << ")" << nl;
    }
}


// ************************************************************************* //


