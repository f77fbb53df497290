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

#include "cartesianGrid2D.H"
#include "volFields.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::cartesianGrid2D::cartesianGrid2D(const fvMesh& mesh)
:
    x0_(0), y0_(0), dx_(0), dy_(0), depth_(0), nx_(0), ny_(0)
{
    const Vector<label>& geomD = mesh.geometricD();
    if (mesh.nGeometricD() != 2 || geomD.z() != -1)
    {
        FatalErrorInFunction
            << "The mesh of " << mesh.time().path()
            << " is not a 2D mesh one cell thick in z" << nl
            << "    dpmFoam2D needs the bed in the x-y plane with the front and"
            << " back patches of type empty (blockMesh: n = (nx ny 1))."
            << exit(FatalError);
    }

    const boundBox& bb = mesh.bounds();
    x0_ = bb.min().x();
    y0_ = bb.min().y();
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
        }
        if (span.z() < (1 - tol)*depth_)
        {
            FatalErrorInFunction
                << "The mesh of " << mesh.time().path()
                << " is not a 2D mesh one cell thick in z: cell " << celli
                << " is " << span.z() << " m thick, the mesh " << depth_
                << " m" << nl
                << "    dpmFoam2D needs the bed in the x-y plane with the front"
                << " and back patches of type empty (blockMesh: n = (nx ny 1))."
                << exit(FatalError);
        }
        const bool sameSize =
            mag(span.x() - dx_) < tol*dx_ && mag(span.y() - dy_) < tol*dy_;
        const bool isBox =
            mag(mesh.V()[celli] - span.x()*span.y()*span.z())
          < tol*mesh.V()[celli];
        if (!sameSize || !isBox)
        {
            FatalErrorInFunction
                << "The mesh of " << mesh.time().path()
                << " is not a uniform Cartesian grid: cell " << celli
                << " at " << mesh.C()[celli] << " is " << span.x() << " x "
                << span.y() << " m, the first cell " << dx_ << " x " << dy_
                << " m" << nl
                << "    dpmFoam2D needs equal rectangular cells"
                << " (blockMesh with simpleGrading (1 1 1))."
                << exit(FatalError);
        }
    }

    nx_ = label(std::round(bb.span().x()/dx_));
    ny_ = label(std::round(bb.span().y()/dy_));
    if (nx_ < 2 || ny_ < 2 || nx_*ny_ != mesh.nCells())
    {
        FatalErrorInFunction
            << "The mesh of " << mesh.time().path() << " has "
            << mesh.nCells() << " cells but its bounding box holds "
            << nx_ << " x " << ny_ << " cells of " << dx_ << " x " << dy_
            << " m; dpmFoam2D needs a full rectangular grid of at least"
            << " 2 x 2 cells" << exit(FatalError);
    }

    cellOfIJ_.setSize(nx_*ny_, -1);
    forAll(mesh.C(), celli)
    {
        const label i = label(std::floor((mesh.C()[celli].x() - x0_)/dx_));
        const label j = label(std::floor((mesh.C()[celli].y() - y0_)/dy_));
        cellOfIJ_[i + nx_*j] = celli;
    }
    if (findIndex(cellOfIJ_, -1) != -1)
    {
        FatalErrorInFunction
            << "The cells of " << mesh.time().path()
            << " do not fill a rectangular grid" << exit(FatalError);
    }
}
