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
    packedBed: the particles of a positions file (initialBed/positions),
    one "class x y" a line ("class x y [z]" in the slab mode).
\*---------------------------------------------------------------------------*/

#include "packedBed.H"
#include "finiteNumber.H"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- A whole number written as one (no trailing characters)
bool readWhole(const std::string& text, label& value)
{
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (*end != '\0' || errno != 0 || v < labelMin || v > labelMax) return false;
    value = label(v);
    return true;
}


} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::packedBed::readPositions(const fileName& file)
{
    std::ifstream is(file);
    if (!is.good())
    {
        FatalIOErrorInFunction(dict_)
            << "Cannot read initialBed/positions " << file << " of "
            << dict_.name() << exit(FatalIOError);
    }
    auto bad = [&](const label lineNo, const std::string& what)
    {
        FatalIOErrorInFunction(dict_)
            << "initialBed/positions " << file << " line " << lineNo << ": "
            << what.c_str() << "; each line is "
            << (slab_ ? "'class x y [z]'" : "'class x y'")
            << " (class index, position in m"
            << (slab_ ? "; z the slab's mid-plane if left out" : "")
            << "), '#' starts a comment" << exit(FatalIOError);
    };

    std::string line;
    label lineNo = 0;
    while (std::getline(is, line))
    {
        ++lineNo;
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream fields(line);
        std::vector<std::string> words;
        for (std::string w; fields >> w;) words.push_back(w);
        if (words.empty()) continue;        // blank or a comment

        const bool hasZ = slab_ && words.size() == 4;
        if (words.size() != 3 && !hasZ)
        {
            bad
            (
                lineNo,
                std::to_string(words.size()) + " fields, "
              + (slab_ ? "3 or 4" : "3")
              + " wanted"
            );
        }
        label classIndex = -1;
        if (!readWhole(words[0], classIndex))
        {
            bad(lineNo, "class '" + words[0] + "' is not a whole number");
        }
        if (classIndex < 0 || classIndex >= classNames_.size())
        {
            bad
            (
                lineNo,
                "class " + words[0] + " is outside [0, "
              + std::to_string(classNames_.size() - 1) + "]"
            );
        }
        scalar xy[3];
        for (label k = 0; k + 1 < label(words.size()); ++k)
        {
            if (!readFiniteNumber(words[k + 1], xy[k]))
            {
                bad
                (
                    lineNo,
                    std::string(1, "xyz"[k]) + " = '" + words[k + 1]
                  + "' is not a finite number"
                );
            }
        }
        if (slab_)
        {
            addListedSphere(classIndex, xy, hasZ);
            continue;
        }
        engine_.guarded
        (
            "Cannot place a particle of initialBed/positions",
            [&]{ engine_.dem().addParticle(classIndex, xy[0], xy[1]); }
        );
    }
    if (!engine_.size())
    {
        FatalIOErrorInFunction(dict_)
            << "initialBed/positions " << file << " of " << dict_.name()
            << " lists no particle (" << lineNo << " lines, none 'class x y')"
            << exit(FatalIOError);
    }
}


void Foam::packedBed::addListedSphere
(
    const label classIndex,
    const scalar xyz[3],
    const bool hasZ
)
{
    const dem::Vector3 p{xyz[0], xyz[1], hasZ ? xyz[2] : 0.5*grid_.depth()};
    engine_.guarded
    (
        "Cannot place a particle of initialBed/positions (the slab's walls"
        " are z = 0 and z = the mesh's thickness)",
        [&]{ engine_.dem().addParticle(classIndex, p); }
    );
}


// ************************************************************************* //
