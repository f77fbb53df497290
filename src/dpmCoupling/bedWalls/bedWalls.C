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

#include "bedWalls.H"
#include "emptyPolyPatch.H"
#include "volMesh.H"
#include "tensor.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace Foam
{
namespace
{

dem::Vector3 toDem(const vector& v)
{
    return dem::Vector3{v.x(), v.y(), v.z()};
}


//- v rounded to a multiple of q: a fit's last bits depend on the order of
//  the mesh's faces and points, which renumberMesh changes, and a state
//  is read only with the walls it was made with
scalar snapped(const scalar v, const scalar q)
{
    return std::round(v/q)*q + 0.0;     // + 0.0: no -0
}

vector snapped(const vector& v, const scalar q)
{
    return vector(snapped(v.x(), q), snapped(v.y(), q), snapped(v.z(), q));
}


} // End anonymous namespace
} // End namespace Foam


Foam::wordList Foam::bedWalls::wallPatches(const fvMesh& mesh)
{
    wordList names;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if
        (
            !isA<emptyPolyPatch>(pp) && !pp.coupled()
         && returnReduce(pp.size(), sumOp<label>()) > 0
        )
        {
            names.append(pp.name());
        }
    }
    return names;
}


namespace Foam
{
namespace
{


//- The fits' values rounded to this fraction of their tolerance: lengths
//  to 1e-12 of the mesh's size, unit vectors to 1e-12
constexpr scalar snap = 1e-6;


[[noreturn]] void refuse
(
    const dictionary& shapes,
    const word& patch,
    const string& why
)
{
    FatalIOErrorInFunction(shapes)
        << "Patch '" << patch << "' in entry 'wallShapes' of "
        << shapes.name() << ": " << why.c_str() << exit(FatalIOError);
    ::abort();
}


dem::WallSettings fitPlane
(
    const dictionary& shapes,
    const polyPatch& pp,
    const scalar tol
)
{
    const vector S = gSum(pp.faceAreas());
    const scalar A = gSum(mag(pp.faceAreas()));
    const vector n = -S/max(mag(S), VSMALL);
    const point c = gSum(mag(pp.faceAreas())*pp.faceCentres())/A;
    scalar worst = 0;
    for (const point& p : pp.localPoints())
    {
        worst = max(worst, mag((p - c) & n));
    }
    reduce(worst, maxOp<scalar>());
    if (!(mag(S) > 0.5*A) || worst > tol)
    {
        refuse
        (
            shapes, pp.name(),
            "its points are up to " + name(worst) + " m off the plane"
            " through its centre (" + name(c.x()) + " " + name(c.y()) + " "
            + name(c.z()) + ") across its faces' mean normal; allowed: a"
            " plane, within " + name(tol) + " m (name the shape it has, or"
            " split the patch into planes)"
        );
    }
    return dem::WallSettings::plane
    (
        toDem(snapped(c, snap*tol)), toDem(snapped(n, snap*bedWalls::fitTolerance))
    );
}


dem::WallSettings fitCylinder
(
    const dictionary& shapes,
    const polyPatch& pp,
    const vector& g,
    const scalar rMin,
    const scalar tol
)
{
    // Coordinates (u, v) across the axis, from the points' mean; the circle
    // u^2 + v^2 = 2a u + 2b v + c by least squares (Kasa's fit: linear)
    const vector axis = -g/mag(g);
    vector e1 = (mag(axis.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0));
    e1 -= (e1 & axis)*axis;
    e1 /= mag(e1);
    const vector e2 = axis ^ e1;

    const pointField& pts = pp.localPoints();
    const point mean =
        gSum(pts)/max(returnReduce(pts.size(), sumOp<label>()), 1);
    tensor M(Zero);
    vector rhs(Zero);
    for (const point& p : pts)
    {
        const scalar u = (p - mean) & e1, v = (p - mean) & e2;
        const vector row(2*u, 2*v, 1);
        M += row*row;
        rhs += (u*u + v*v)*row;
    }
    reduce(M, sumOp<tensor>());
    reduce(rhs, sumOp<vector>());
    const scalar D = det(M);
    if (!(mag(D) > VSMALL))
    {
        refuse
        (
            shapes, pp.name(),
            "its points do not span a circle across the axis (the direction"
            " of gravity); allowed: a cylinder about that axis"
        );
    }
    const vector abc = inv(M) & rhs;
    const point centre = mean + abc.x()*e1 + abc.y()*e2;

    // The radius: the points' mean distance from the axis
    auto radial = [&](const point& p)
    {
        const vector d = p - centre;
        return d - (d & axis)*axis;
    };
    scalar sumR = 0;
    for (const point& p : pts) sumR += mag(radial(p));
    const scalar R =
        returnReduce(sumR, sumOp<scalar>())
       /max(returnReduce(pts.size(), sumOp<label>()), 1);

    scalar worst = 0;
    for (const point& p : pts) worst = max(worst, mag(mag(radial(p)) - R));
    reduce(worst, maxOp<scalar>());

    // Faces facing away from the axis (particles inside), and how far the
    // flat faces lie inside the exact cylinder
    label inward = 0;
    scalar sagitta = 0;
    forAll(pp, f)
    {
        const vector r = radial(pp.faceCentres()[f]);
        if ((pp.faceAreas()[f] & r) <= 0) ++inward;
        sagitta = max(sagitta, R - mag(r));
    }
    reduce(inward, sumOp<label>());
    reduce(sagitta, maxOp<scalar>());

    const string where =
        "the cylinder about the axis along gravity through ("
      + name(centre.x()) + " " + name(centre.y()) + " " + name(centre.z())
      + "), radius " + name(R) + " m";
    if (worst > tol)
    {
        refuse
        (
            shapes, pp.name(),
            "its points are up to " + name(worst) + " m off " + where
          + " (the least-squares fit); allowed: a cylinder, within "
          + name(tol) + " m"
        );
    }
    if (inward > 0)
    {
        refuse
        (
            shapes, pp.name(),
            name(inward) + " of its faces face the axis of " + where
          + "; allowed: the gas inside the cylinder, every face facing out"
        );
    }
    if (!(sagitta < rMin))
    {
        refuse
        (
            shapes, pp.name(),
            "its flat faces lie up to " + name(sagitta) + " m inside "
          + where + ", not less than the smallest particle radius "
          + name(rMin) + " m: a sphere touching the wall would have its"
            " centre outside the gas; allowed: less (more faces round the"
            " wall)"
        );
    }
    return dem::WallSettings::cylinder
    (
        toDem(snapped(centre, snap*tol)),
        toDem(snapped(axis, snap*bedWalls::fitTolerance)),
        snapped(R, snap*tol)
    );
}

} // End anonymous namespace
} // End namespace Foam


// * * * * * * * * * * * * * * * * Functions  * * * * * * * * * * * * * * * //

std::vector<dem::WallSettings> Foam::bedWalls::read
(
    const dictionary& dict,
    const fvMesh& mesh,
    const vector& g,
    const scalar rMin
)
{
    const boundBox& bb = mesh.bounds();
    const scalar tol = fitTolerance*mag(bb.span());
    const wordList patches(wallPatches(mesh));

    const dictionary* shapes = dict.findDict("wallShapes", keyType::LITERAL);
    if (!shapes)
    {
        if (dict.found("wallShapes", keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'wallShapes' in " << dict.name() << " is not a"
                << " dictionary; allowed: wallShapes { <patch> plane; or"
                << " <patch> cylinder; ... } naming each of the patches "
                << patches << exit(FatalIOError);
        }
        // The box's six walls: the mesh must fill its box
        const scalar V = gSum(mesh.V());
        if (mag(V - bb.volume()) > 1e-9*bb.volume())
        {
            FatalIOErrorInFunction(dict)
                << "The mesh fills " << 100*V/bb.volume() << " % of its"
                << " bounding box " << bb << ", and " << dict.name()
                << " has no entry 'wallShapes': the particles' walls would"
                << " be the box's, and particles would leave the gas."
                << nl << "    Name each boundary patch's shape: wallShapes"
                << " { <patch> plane; <patch> cylinder; ... } for the"
                << " patches " << patches << exit(FatalIOError);
        }
        return {};
    }

    if (!mag(g))
    {
        FatalIOErrorInFunction(*shapes)
            << "wallShapes in " << dict.name() << " needs gravity (the"
            << " cylinders' axis): constant/g is zero" << exit(FatalIOError);
    }

    std::vector<dem::WallSettings> walls;
    for (const word& key : shapes->toc())
    {
        if (!patches.found(key))
        {
            FatalIOErrorInFunction(*shapes)
                << "Patch '" << key << "' in entry 'wallShapes' of "
                << dict.name() << " is not a boundary patch the particles"
                << " can meet; allowed: " << patches << exit(FatalIOError);
        }
    }
    for (const word& patch : patches)
    {
        if (!shapes->found(patch, keyType::LITERAL))
        {
            FatalIOErrorInFunction(*shapes)
                << "Patch '" << patch << "' of the mesh is missing from"
                << " entry 'wallShapes' of " << dict.name() << "; allowed:"
                << " each of the patches " << patches << " named with its"
                << " shape (plane or cylinder)" << exit(FatalIOError);
        }
        const word shape = shapes->get<word>(patch, keyType::LITERAL);
        const polyPatch& pp = mesh.boundaryMesh()[patch];
        if (shape == "plane")
        {
            walls.push_back(fitPlane(*shapes, pp, tol));
        }
        else if (shape == "cylinder")
        {
            walls.push_back(fitCylinder(*shapes, pp, g, rMin, tol));
        }
        else
        {
            refuse
            (
                *shapes, patch,
                "shape '" + shape + "'; allowed: plane or cylinder"
            );
        }
    }
    return walls;
}


// ************************************************************************* //
