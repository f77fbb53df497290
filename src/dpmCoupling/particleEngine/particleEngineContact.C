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
    particleEngine: constant/particleProperties' contact dictionary
    translated into the DEM's contact settings: the law, the global
    coefficients, and the coefficients of the pairs of classes (pairs
    <classA>-<classB>) and of the classes on the walls (walls <class>) that
    replace them. The names are checked here (a class of classes, each pair
    once), the ranges of a pair's or a wall's entries too, in the words of
    the dictionary; the unknown entries by particleChecks.
\*---------------------------------------------------------------------------*/

#include "particleEngine.H"
#include "positiveEntry.H"
#include "particlePropertiesEntries.H"

#include <optional>
#include <utility>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- Warning naming the Hertz-Mindlin law's entries given to the linear law,
//  which reads none of them: said, not ignored silently
void noteHertzEntries
(
    const fileName& file,
    const dictionary& classes,
    const dictionary& contact
)
{
    std::string unused;
    const auto add = [&unused](const std::string& entry)
    {
        unused += (unused.empty() ? "" : ", ") + entry;
    };
    for (const char* key : {"wallYoungsModulus", "wallPoissonRatio", "impactSpeed"})
    {
        if (contact.found(key, keyType::LITERAL)) add("contact/" + word(key));
    }
    for (const word& name : classes.sortedToc())
    {
        const dictionary* c = classes.findDict(name);
        for (const char* key : {"youngsModulus", "poissonRatio"})
        {
            if (c && c->found(key, keyType::LITERAL))
            {
                add("classes/" + name + "/" + word(key));
            }
        }
    }
    if (!unused.empty())
    {
        WarningInFunction
            << file << ": " << unused.c_str()
            << " not used: the contactLaw is linear (kn, kt and restitution"
            << " set the contact); select contactLaw HertzMindlin for them,"
            << " or remove the entries" << endl;
    }
}


//- "small, large"
std::string listed(const wordList& names)
{
    std::string text;
    for (const word& n : names) text += (text.empty() ? "" : ", ") + n;
    return text;
}


//- The optional coefficient `name` of a pair's or a wall's dictionary, in
//  the range of the global entry it replaces: a restitution in (0, 1], a
//  friction in [0, inf)
std::optional<double> ownCoefficient(const dictionary& d, const word& name)
{
    if (!d.found(name, keyType::LITERAL))
    {
        return std::nullopt;
    }
    const bool restitution = name.compare(0, 11, "restitution") == 0;
    return boundedEntry(d, name, 0, restitution ? 1 : GREAT, restitution);
}


//- The sub-dictionary `name` of contact (null if absent); a FatalIOError if
//  it is not a dictionary
const dictionary* ownDictionary(const dictionary& contact, const word& name)
{
    if
    (
        contact.found(name, keyType::LITERAL)
     && !contact.isDict(name, keyType::LITERAL)
    )
    {
        FatalIOErrorInFunction(contact)
            << "Entry '" << name << "' in " << contact.name()
            << " is not a dictionary; allowed: " << name << " { ... }"
            << " of sub-dictionaries (docs/user-guide/dictionaries.md)"
            << exit(FatalIOError);
    }
    return contact.findDict(name, keyType::LITERAL);
}


//- Whether keyword `key` is one of a dictionary's own entries (not a
//  directive or a macro, which OpenFOAM has expanded)
bool isEntry(const keyType& key)
{
    return !key.empty() && key[0] != '#' && key[0] != '$';
}


//- The entry `e` of `parent` as a dictionary; a FatalIOError naming what
//  it should hold if it is not one
const dictionary& entryDict
(
    const dictionary& parent,
    const entry& e,
    const wordList& allowed
)
{
    if (!e.isDict())
    {
        FatalIOErrorInFunction(parent)
            << "Entry '" << e.keyword().c_str() << "' in " << parent.name()
            << " is not a dictionary; allowed: " << e.keyword().c_str()
            << " { any of " << listed(allowed).c_str() << " }"
            << exit(FatalIOError);
    }
    return e.dict();
}


//- The classes (a, b) of pair name `key`, <a>-<b> in either order: every
//  split at a '-' into two class names (a class name may hold a '-')
std::vector<std::pair<label, label>> pairClasses
(
    const word& key,
    const wordList& classNames
)
{
    std::vector<std::pair<label, label>> splits;
    for
    (
        std::string::size_type at = key.find('-');
        at != std::string::npos;
        at = key.find('-', at + 1)
    )
    {
        const label a = classNames.find(word(key.substr(0, at)));
        const label b = classNames.find(word(key.substr(at + 1)));
        if (a >= 0 && b >= 0)
        {
            splits.emplace_back(a, b);
        }
    }
    return splits;
}


//- contact/pairs: the coefficients of each pair of classes given
std::vector<dem::PairContactSettings> readPairs
(
    const dictionary& contact,
    const wordList& classNames
)
{
    std::vector<dem::PairContactSettings> pairs;
    const dictionary* dict = ownDictionary(contact, "pairs");
    if (!dict)
    {
        return pairs;
    }
    namespace names = particlePropertiesEntries;
    std::vector<word> keys;
    for (const entry& e : *dict)
    {
        if (!isEntry(e.keyword())) continue;
        const word key(e.keyword());
        const dictionary& own = entryDict(*dict, e, names::pairContact());
        const auto splits = pairClasses(key, classNames);
        if (splits.size() != 1)
        {
            FatalIOErrorInFunction(*dict)
                << "Entry '" << key << "' in " << dict->name()
                << (
                       splits.empty()
                     ? " is not a pair of classes"
                     : " names more than one pair of classes"
                   )
                << "; allowed: <classA>-<classB>, in either order, of the"
                << " classes " << listed(classNames).c_str()
                << " (e.g. " << classNames.first() << "-" << classNames.last() << ")"
                << exit(FatalIOError);
        }
        const auto [a, b] = splits.front();
        for (std::size_t q = 0; q < pairs.size(); ++q)
        {
            const dem::PairContactSettings& p = pairs[q];
            if ((p.classA == a && p.classB == b) || (p.classA == b && p.classB == a))
            {
                FatalIOErrorInFunction(*dict)
                    << "Entries '" << keys[q] << "' and '" << key << "' in "
                    << dict->name() << " are the same pair of classes;"
                    << " allowed: each pair once, in either order"
                    << exit(FatalIOError);
            }
        }
        dem::PairContactSettings p;
        p.classA = int(a);
        p.classB = int(b);
        p.restitution = ownCoefficient(own, "restitution");
        p.frictionParticle = ownCoefficient(own, "frictionParticle");
        p.rollingFriction = ownCoefficient(own, "rollingFriction");
        pairs.push_back(p);
        keys.push_back(key);
    }
    return pairs;
}


//- contact/walls: the coefficients of each class given against the walls
std::vector<dem::WallContactSettings> readWalls
(
    const dictionary& contact,
    const wordList& classNames
)
{
    std::vector<dem::WallContactSettings> walls;
    const dictionary* dict = ownDictionary(contact, "walls");
    if (!dict)
    {
        return walls;
    }
    namespace names = particlePropertiesEntries;
    for (const entry& e : *dict)
    {
        if (!isEntry(e.keyword())) continue;
        const word key(e.keyword());
        const dictionary& own = entryDict(*dict, e, names::wallContact());
        const label a = classNames.find(key);
        if (a < 0)
        {
            FatalIOErrorInFunction(*dict)
                << "Entry '" << key << "' in " << dict->name()
                << " is not a class; allowed: the classes "
                << listed(classNames).c_str() << exit(FatalIOError);
        }
        dem::WallContactSettings w;
        w.classIndex = int(a);
        w.restitutionWall = ownCoefficient(own, "restitutionWall");
        w.frictionWall = ownCoefficient(own, "frictionWall");
        w.rollingFrictionWall = ownCoefficient(own, "rollingFrictionWall");
        walls.push_back(w);
    }
    return walls;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

dem::ContactSettings Foam::particleEngine::contactSettings() const
{
    const dictionary& classes = dict_.subDict("classes");
    const dictionary& contact = dict_.subOrEmptyDict("contact");
    dem::ContactSettings cs;
    const word law =
        contact.lookupOrDefault<word>("contactLaw", dem::contactLawName(cs.law));
    try
    {
        cs.law = dem::contactLawFromName(law);
    }
    catch (const dem::Error&)
    {
        FatalIOErrorInFunction(contact)
            << "Entry 'contactLaw' = " << law << " in " << contact.name()
            << " is not allowed; allowed: linear (the paper's, default) or"
            << " HertzMindlin (docs/theory/dem.md, \"The Hertz-Mindlin law\")"
            << exit(FatalIOError);
    }
    if (cs.law == dem::ContactLawType::linear)
    {
        noteHertzEntries(dict_.name(), classes, contact);
    }
    cs.wallYoungsModulus =
        contact.lookupOrDefault<scalar>
        (
            "wallYoungsModulus", cs.wallYoungsModulus
        );
    cs.wallPoissonRatio =
        contact.lookupOrDefault<scalar>
        (
            "wallPoissonRatio", cs.wallPoissonRatio
        );
    cs.impactSpeed = contact.lookupOrDefault<scalar>("impactSpeed", cs.impactSpeed);
    cs.kn = contact.lookupOrDefault<scalar>("kn", cs.kn);
    cs.kt = contact.lookupOrDefault<scalar>("kt", cs.kt);
    cs.restitution = contact.lookupOrDefault<scalar>("restitution", cs.restitution);
    cs.restitutionWall =
        contact.lookupOrDefault<scalar>("restitutionWall", cs.restitutionWall);
    cs.frictionParticle =
        contact.lookupOrDefault<scalar>("frictionParticle", cs.frictionParticle);
    cs.frictionWall = contact.lookupOrDefault<scalar>("frictionWall", cs.frictionWall);
    cs.tangentialDampingRatio =
        contact.lookupOrDefault<scalar>
        (
            "tangentialDampingRatio", cs.tangentialDampingRatio
        );
    cs.rollingFriction =
        contact.lookupOrDefault<scalar>("rollingFriction", cs.rollingFriction);
    cs.rollingFrictionWall =
        contact.lookupOrDefault<scalar>("rollingFrictionWall", cs.rollingFrictionWall);
    cs.pairs = readPairs(contact, classNames_);
    cs.walls = readWalls(contact, classNames_);
    return cs;
}


// ************************************************************************* //
