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
    packedBed: the bed's recipe of initialBed (counts, packing region, seed,
    settling, the settle friction) and its placed particles
    (initialBed/place).
\*---------------------------------------------------------------------------*/

#include "packedBed.H"
#include "mathematicalConstants.H"

#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- initialBed/settleFriction of `bed` (in `file`): none if absent, else a
//  finite number >= 0; a FatalIOError naming the file, the entry and the
//  range otherwise (a negative value, nan, inf, a word, several tokens, a
//  dictionary)
std::optional<double> settleFriction
(
    const dictionary& bed,
    const fileName& file
)
{
    const entry* e = bed.findEntry("settleFriction", keyType::LITERAL);
    if (!e)
    {
        return std::nullopt;
    }
    const char* meaning =
        ": the sliding friction coefficient of every contact while the bed"
        " settles (leave it out for the contacts' own)";
    if (e->isStream())
    {
        ITstream& is = e->stream();
        if (is.size() == 1 && is[0].isNumber())
        {
            const scalar mu = is[0].number();
            if (std::isfinite(mu) && mu >= 0)
            {
                return mu;
            }
            FatalIOErrorInFunction(bed)
                << "Entry 'settleFriction' = " << mu << " in initialBed of "
                << file << " is outside the allowed range [0, inf)"
                << meaning << exit(FatalIOError);
        }
    }
    OStringStream text;
    if (e->isStream())
    {
        ITstream& is = e->stream();
        forAll(is, k)
        {
            text<< (k ? " " : "") << is[k];
        }
    }
    else
    {
        text<< "a dictionary";
    }
    FatalIOErrorInFunction(bed)
        << "Entry 'settleFriction' = " << text.str().c_str()
        << " in initialBed of " << file << " is not a finite number in the"
        << " allowed range [0, inf)" << meaning << exit(FatalIOError);
    return std::nullopt;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

dem::BedRecipe Foam::packedBed::recipe() const
{
    const dictionary& bed = dict_.subDict("initialBed");
    dem::BedRecipe r;
    r.countPerClass = engine_.classCounts();
    const scalar width = grid_.xMax() - grid_.xMin();
    const dem::Settings& s = engine_.dem().settings();
    scalar area = 0;
    forAll(classNames_, k)
    {
        // pi/4 E[d^2] a disc of a distribution
        const dem::ParticleClass& c = s.classes[k];
        if (c.distribution.type == dem::DiameterDistributionType::single)
        {
            const scalar d = c.diameter;
            area += r.countPerClass[k]*constant::mathematical::pi*d*d/4;
        }
        else
        {
            area +=
                r.countPerClass[k]*constant::mathematical::pi
               *dem::diameterMoment(c, 2)/4;
        }
    }
    const scalar filled =
        slab_ ? slabPackHeight(r.countPerClass) : 3*area/width;

    // The region holds at least one of the largest particles: a few
    // particles fill less than a row, so their default is one diameter
    const scalarList largestOf(particleEngine::largestDiametersOf(s));
    label largest = 0;
    forAll(classNames_, k)
    {
        if (largestOf[k] > largestOf[largest])
        {
            largest = k;
        }
    }
    const scalar dMax = largestOf[largest];
    const scalar columnHeight = grid_.yMax() - grid_.yMin();
    if (width < dMax || columnHeight < dMax)
    {
        FatalIOErrorInFunction(dict_)
            << "The column of system/bedGeometry (width " << width
            << " m, height " << columnHeight << " m) is narrower than a"
            << " particle of class '" << classNames_[largest] << "' (d = "
            << dMax << " m, " << dict_.name() << "): make width and height"
            << " larger (then blockMesh) or the particles smaller"
            << exit(FatalIOError);
    }
    const scalar packHeight = bed.lookupOrDefault<scalar>
    (
        "packHeight", min(max(filled, dMax), columnHeight)
    );
    if (packHeight < dMax || packHeight > columnHeight)
    {
        FatalIOErrorInFunction(bed)
            << "Entry 'packHeight' = " << packHeight << " in initialBed of "
            << dict_.name() << " is outside the allowed range [" << dMax
            << ", " << columnHeight << "]: the packing region must hold a"
            << " particle of class '" << classNames_[largest] << "' (d = "
            << dMax << " m) and fit in the column (height " << columnHeight
            << " m, system/bedGeometry); set initialBed/packHeight in that"
            << " range, or leave it out (the default follows the counts)"
            << exit(FatalIOError);
    }
    r.region =
        dem::Box
        {
            grid_.xMin(), grid_.xMax(), grid_.yMin(), grid_.yMin() + packHeight
        };
    r.seed = std::uint64_t(bed.lookupOrDefault<label>("seed", 1));
    r.settleTime = bed.lookupOrDefault<scalar>("settleTime", 1.0);
    r.keTolerance = 0;
    r.placed = placed(r);
    r.settleFriction = settleFriction(bed, dict_.name());
    return r;
}


Foam::scalar Foam::packedBed::slabPackHeight
(
    const std::vector<int>& counts
) const
{
    // Random sequential addition jams near a solid fraction of 0.38 in 3D
    // (0.55 for discs, packed at 1/3): the spheres are packed at 1/5
    const scalarList d3
    (
        particleEngine::classDiameterMoments(engine_.dem().settings(), 3)
    );
    scalar V = 0;
    forAll(classNames_, k)
    {
        V += counts[k]*constant::mathematical::pi*d3[k]/6;
    }
    // The bed's cross-section: the box's, or a vessel's of other walls
    // (the mesh's volume over its height: a prism along gravity)
    const scalar width = grid_.xMax() - grid_.xMin();
    const scalar crossSection =
        engine_.dem().settings().walls.empty()
      ? width*grid_.depth()
      : gSum(grid_.cellVolumes())/(grid_.yMax() - grid_.yMin());
    return 5*V/crossSection;
}


std::vector<dem::PlacedParticle> Foam::packedBed::placed
(
    const dem::BedRecipe& r
) const
{
    const dictionary& bed = dict_.subDict("initialBed");
    const dictionary* place = bed.findDict("place", keyType::LITERAL);
    std::vector<dem::PlacedParticle> out;
    if (!place && bed.found("place", keyType::LITERAL))
    {
        FatalIOErrorInFunction(bed)
            << "Entry 'place' of initialBed in " << dict_.name() << " is not"
            << " a dictionary; allowed: place { <class> { positions ((x y z)"
            << " ...); random <count>; } ... }" << exit(FatalIOError);
    }
    if (!place)
    {
        return out;
    }
    for (const entry& e : *place)
    {
        if (!classNames_.found(e.keyword()) || !e.isDict())
        {
            FatalIOErrorInFunction(*place)
                << "Entry '" << e.keyword() << "' of initialBed/place in "
                << dict_.name() << " is not a class's dictionary; allowed: a"
                << " dictionary named for one of the classes "
                << classNames_ << " with 'positions' and/or 'random'"
                << exit(FatalIOError);
        }
    }
    // Class by class in the classes' order: the given positions, then the
    // random ones
    forAll(classNames_, k)
    {
        const dictionary* c = place->findDict(classNames_[k], keyType::LITERAL);
        if (!c)
        {
            continue;
        }
        if (!c->found("positions") && !c->found("random"))
        {
            FatalIOErrorInFunction(*c)
                << "Entry 'place/" << classNames_[k] << "' of initialBed in "
                << dict_.name() << " lays no particle; allowed: 'positions'"
                << " (a list of (x y z), m) and/or 'random' (a count >= 0)"
                << exit(FatalIOError);
        }
        if (c->found("positions"))
        {
            for (const vector& p : c->get<List<vector>>("positions"))
            {
                dem::PlacedParticle q;
                q.classIndex = int(k);
                q.position = dem::Vector3{p.x(), p.y(), p.z()};
                out.push_back(q);
            }
        }
        const label n = c->lookupOrDefault<label>("random", 0);
        if (n < 0)
        {
            FatalIOErrorInFunction(*c)
                << "Entry 'random' = " << n << " in " << c->name()
                << " is outside the allowed range [0, inf)"
                << exit(FatalIOError);
        }
        for (label q = 0; q < n; ++q)
        {
            dem::PlacedParticle p;
            p.classIndex = int(k);
            p.random = true;
            out.push_back(p);
        }
    }
    // Where they fit: in the packing region, apart, within the counts
    dem::BedRecipe withPlaced(r);
    withPlaced.placed = out;
    try
    {
        dem::checkPlacements(engine_.dem().settings(), withPlaced);
    }
    catch (const dem::Error& err)
    {
        FatalIOErrorInFunction(*place)
            << "Entry 'place' of initialBed in " << dict_.name() << ": "
            << err.what() << "; the packing region is the column's width,"
            << " from its floor to packHeight = " << r.region.yMax - r.region.yMin
            << " m" << (slab_ ? ", through the slab's depth" : "") << ")"
            << exit(FatalIOError);
    }
    return out;
}


// ************************************************************************* //
