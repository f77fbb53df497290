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
Description
    The walls the spheres meet, fitted to the patches of the case's meshes
    (bedWalls), against the shapes blockMesh made them (the cylinder's
    blockMeshDict: radius 50 mm about the y axis, 100 mm tall, 24 faces
    round); and the solver's velocity rebuilt from the face fluxes
    (staticReconstruction), exact for a uniform flow on any mesh.

\*---------------------------------------------------------------------------*/

#include "unstructuredGridTests.H"
#include "bedWalls.H"
#include "staticReconstruction.H"
#include "IStringStream.H"

using namespace Foam;

namespace
{

const vector gravity(0, -9.81, 0);

dictionary shapes(const char* entries)
{
    return dictionary(IStringStream(entries)());
}

const char* const cylinderShapes =
    "wallShapes { inlet plane; outlet plane; walls cylinder; }";

}


// The inlet (y = 0) and outlet (y = 0.1 m) as planes whose normals point
// into the gas, the side as the cylinder of radius 50 mm about the y axis
TEST(BedWalls, PlanesAndTheCylinderOfTheOGrid)
{
    const std::vector<dem::WallSettings> w =
        bedWalls::read(shapes(cylinderShapes), cylinderMesh(), gravity, 1e-3);
    ASSERT_EQ(w.size(), 3u);

    const dem::WallSettings& inlet = w[0];
    EXPECT_EQ(inlet.shape, dem::WallShape::plane);
    couplingTest::checkAbsolute("inlet: y", inlet.point.y, 0, 1e-12);
    couplingTest::checkAbsolute("inlet: normal y", inlet.normal.y, 1, 1e-12);
    couplingTest::checkAbsolute
    (
        "inlet: normal x, z", mag(inlet.normal.x) + mag(inlet.normal.z), 0,
        1e-12
    );

    const dem::WallSettings& outlet = w[1];
    EXPECT_EQ(outlet.shape, dem::WallShape::plane);
    couplingTest::checkAbsolute("outlet: y", outlet.point.y, 0.1, 1e-12);
    couplingTest::checkAbsolute
    (
        "outlet: normal y", outlet.normal.y, -1, 1e-12
    );

    const dem::WallSettings& side = w[2];
    EXPECT_EQ(side.shape, dem::WallShape::cylinder);
    couplingTest::check("side: radius", side.radius, 0.05, 1e-9);
    couplingTest::checkAbsolute("side: axis x", side.point.x, 0, 1e-9);
    couplingTest::checkAbsolute("side: axis z", side.point.z, 0, 1e-9);
    couplingTest::checkAbsolute("side: axis y", side.axis.y, 1, 1e-12);
}


// A patch called by another shape than its own is refused, naming it
TEST(BedWalls, RefusesAPatchOfAnotherShape)
{
    const std::string planeSide = errorOf([]{
        bedWalls::read
        (
            shapes("wallShapes { inlet plane; outlet plane; walls plane; }"),
            cylinderMesh(), gravity, 1e-3
        );
    });
    EXPECT_TRUE(says(planeSide, "Patch 'walls'")) << planeSide;
    EXPECT_TRUE(says(planeSide, "off the plane")) << planeSide;

    const std::string cylinderInlet = errorOf([]{
        bedWalls::read
        (
            shapes("wallShapes { inlet cylinder; outlet plane; walls cylinder; }"),
            cylinderMesh(), gravity, 1e-3
        );
    });
    EXPECT_TRUE(says(cylinderInlet, "Patch 'inlet'")) << cylinderInlet;
    EXPECT_TRUE(says(cylinderInlet, "off the cylinder")) << cylinderInlet;

    const std::string sphere = errorOf([]{
        bedWalls::read
        (
            shapes("wallShapes { inlet plane; outlet plane; walls sphere; }"),
            cylinderMesh(), gravity, 1e-3
        );
    });
    EXPECT_TRUE(says(sphere, "plane or cylinder")) << sphere;
}


// Every patch the particles can meet is named, once; a name that is not a
// patch is refused with the patches listed
TEST(BedWalls, RefusesAPatchMissingOrUnknown)
{
    const std::string missing = errorOf([]{
        bedWalls::read
        (
            shapes("wallShapes { inlet plane; walls cylinder; }"),
            cylinderMesh(), gravity, 1e-3
        );
    });
    EXPECT_TRUE(says(missing, "Patch 'outlet' of the mesh is missing"))
        << missing;

    const std::string unknown = errorOf([]{
        bedWalls::read
        (
            shapes
            (
                "wallShapes { inlet plane; outlet plane; walls cylinder;"
                " top plane; }"
            ),
            cylinderMesh(), gravity, 1e-3
        );
    });
    EXPECT_TRUE(says(unknown, "Patch 'top'")) << unknown;
    EXPECT_TRUE(says(unknown, "outlet")) << unknown;
}


// The 24 flat faces round the wall lie inside the cylinder by up to
// R (1 - cos(pi/24)) = 0.4278 mm at their centres: spheres of a smaller
// radius would touch the wall with their centres outside the gas
TEST(BedWalls, RefusesFacesDeeperThanTheSmallestRadius)
{
    const scalar sagitta =
        0.05*(1 - std::cos(constant::mathematical::pi/24));
    const std::string deeper = errorOf([&]{
        bedWalls::read
        (
            shapes(cylinderShapes), cylinderMesh(), gravity, 0.99*sagitta
        );
    });
    EXPECT_TRUE(says(deeper, "flat faces lie up to")) << deeper;

    const std::string shallower = errorOf([&]{
        bedWalls::read
        (
            shapes(cylinderShapes), cylinderMesh(), gravity, 1.01*sagitta
        );
    });
    EXPECT_EQ(shallower, "");
}


// Without the entry the walls are the box's: a box mesh passes, the
// cylinder (pi/4 of its box, less the faces' cut) is refused
TEST(BedWalls, WithoutTheEntryTheMeshMustBeItsBox)
{
    EXPECT_TRUE
    (
        bedWalls::read(dictionary(), boxMesh(), gravity, 1e-3).empty()
    );
    const std::string cylinder = errorOf([]{
        bedWalls::read(dictionary(), cylinderMesh(), gravity, 1e-3);
    });
    EXPECT_TRUE(says(cylinder, "no entry 'wallShapes'")) << cylinder;
}


// The flux of a uniform velocity, U.S_f, rebuilt into the cells gives U
// back in every cell (sum_f n_f (U.S_f) = (sum_f n_f S_f).U), whatever
// the mesh: on the cylinder's O-grid and the warped box the cells' tensors
// have off-diagonal parts
void checkUniformFlow(const fvMesh& mesh, const word& name)
{
    const vector U(0.3, 2.1, -0.7);
    const surfaceScalarField phi
    (
        IOobject("phi", mesh.time().timeName(), mesh),
        mesh.Sf() & dimensionedVector("U", dimVelocity, U)
    );
    const staticReconstruction reconstruct(mesh);
    const volVectorField Ucells(reconstruct(phi));
    scalar worst = 0;
    forAll(Ucells, celli)
    {
        worst = max(worst, mag(Ucells[celli] - U));
    }
    couplingTest::checkAbsolute
    (
        name + ": largest error of the rebuilt uniform flow, m/s", worst, 0,
        1e-12*mag(U)
    );
}

TEST(StaticReconstruction, UniformFlowExactOnTheBox)
{
    checkUniformFlow(boxMesh(), "box");
}

TEST(StaticReconstruction, UniformFlowExactOnTheCylinder)
{
    checkUniformFlow(cylinderMesh(), "cylinder");
}

TEST(StaticReconstruction, UniformFlowExactOnTheWarpedBox)
{
    checkUniformFlow(warpedMesh(), "warped box");
}


// ************************************************************************* //
