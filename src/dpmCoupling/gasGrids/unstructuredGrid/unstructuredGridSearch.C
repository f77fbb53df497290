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
    unstructuredGrid: locating points. OpenFOAM's test of a cell (its tets)
    and search (the octree) decide; a walk across the face planes from a
    particle's last cell finds the cell to test first.
\*---------------------------------------------------------------------------*/

#include "unstructuredGrid.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

bool Foam::unstructuredGrid::behindFaces
(
    const point& p,
    const label celli
) const
{
    const vectorField& Cf = mesh_.faceCentres();
    const labelList& owner = mesh_.faceOwner();
    for (const label facei : mesh_.cells()[celli])
    {
        const scalar s = (p - Cf[facei]) & faceNormals_[facei];
        if (owner[facei] == celli ? s > 0 : s < 0)
        {
            return false;
        }
    }
    return true;
}


Foam::label Foam::unstructuredGrid::walk
(
    const point& p,
    const label seed,
    bool& beyond,
    const label maxSteps
) const
{
    const vectorField& Cf = mesh_.faceCentres();
    const labelList& owner = mesh_.faceOwner();
    const labelList& neighbour = mesh_.faceNeighbour();
    const label nInternal = mesh_.nInternalFaces();

    beyond = false;
    label celli = seed;
    for (label step = 0; step < maxSteps; ++step)
    {
        // The internal and the boundary face p lies farthest beyond (out
        // of celli); across an internal face first, so that a point beyond
        // the boundary ends in the cell inside nearest it
        label across = -1, wall = -1;
        scalar farthest = 0, farthestWall = 0;
        for (const label facei : mesh_.cells()[celli])
        {
            scalar s = (p - Cf[facei]) & faceNormals_[facei];
            if (owner[facei] != celli) s = -s;
            if (facei < nInternal)
            {
                if (s > farthest)
                {
                    farthest = s;
                    across = facei;
                }
            }
            else if (s > farthestWall)
            {
                farthestWall = s;
                wall = facei;
            }
        }
        if (across == -1)
        {
            beyond = wall != -1;
            return celli;
        }
        celli = owner[across] == celli ? neighbour[across] : owner[across];
    }
    return -1;
}


Foam::label Foam::unstructuredGrid::locate
(
    const point& p,
    const label seed
) const
{
    if (seed >= 0 && seed < mesh_.nCells())
    {
        bool beyond = false;
        const label celli = walk(p, seed, beyond);
        if (celli >= 0 && !beyond)
        {
            // The tet test decides, as polyMesh::findCell's: the cell, else
            // a face neighbour (a warped face's plane and its tets differ)
            if (mesh_.pointInCell(p, celli))
            {
                return celli;
            }
            for (const label nbr : mesh_.cellCells()[celli])
            {
                if (mesh_.pointInCell(p, nbr))
                {
                    return nbr;
                }
            }
        }
    }
    return mesh_.findCell(p);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::unstructuredGrid::findCell(const point& p) const
{
    return mesh_.findCell(p);
}


// ************************************************************************* //
