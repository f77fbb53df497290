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
    cartesianGrid: system/bedGeometry, from which blockMeshDict makes the
    mesh, against the grid's box and cells (a dictionary edited without a
    new blockMesh).
\*---------------------------------------------------------------------------*/

#include "cartesianGrid.H"
#include "knownEntries.H"
#include "OStringStream.H"
#include "Time.H"

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

//- The entries of system/bedGeometry (the mesh's size and cells)
const wordList& bedGeometryEntries()
{
    static const wordList names{"width", "height", "depth", "nx", "ny", "nz"};
    return names;
}

//- The value of `key` in dict if it is a plain number
bool plainNumber(const dictionary& dict, const word& key, scalar& value)
{
    const entry* e = dict.findEntry(key, keyType::LITERAL);
    if (!e || !e->isStream()) return false;
    ITstream& is = e->stream();
    if (is.size() != 1 || !is[0].isNumber()) return false;
    value = is[0].number();
    return true;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::cartesianGrid::checkBedGeometry() const
{
    const fileName systemDir(mesh_.time().path()/mesh_.time().system());
    const fileName file(systemDir/"bedGeometry");
    if (!isFile(file)) return;

    const dictionary bed(readDictionary(file));
    checkKnownEntries(bed, bedGeometryEntries(), "system/bedGeometry");

    // blockMeshDict may scale the geometry: its `scale 0.001;` (or the
    // older convertToMeters), if written as a number
    scalar scale = 1;
    {
        std::ifstream is(systemDir/"blockMeshDict");
        std::stringstream text;
        text << is.rdbuf();
        const std::string s(text.str());
        std::smatch match;
        const std::regex entry
        (
            R"((^|\n)\s*(scale|convertToMeters)\s+([-+0-9.eE]+)\s*;)"
        );
        if (std::regex_search(s, match, entry))
        {
            scale = std::stod(match[3]);
        }
    }

    const scalar meshValues[] =
    {
        xMax() - xMin(), yMax() - yMin(), depth_,
        scalar(nx_), scalar(ny_), scalar(nz_)
    };
    OStringStream differences;
    forAll(bedGeometryEntries(), k)
    {
        const word& key = bedGeometryEntries()[k];
        const bool isCount = k >= 3;
        const bool found = bed.found(key, keyType::LITERAL);
        // A grid one cell deep needs no nz; every other entry is read by
        // blockMeshDict and must be there
        if (!found && key != "nz")
        {
            FatalIOErrorInFunction(bed)
                << "Entry '" << key << "' is missing in system/bedGeometry;"
                << " blockMeshDict makes the mesh from it" << exit(FatalIOError);
        }
        scalar value = 1;
        if (found && !plainNumber(bed, key, value))
        {
            FatalIOErrorInFunction(bed)
                << "Entry '" << key << "' in system/bedGeometry is not a"
                << " number; allowed: " << (isCount ? "a whole number of"
                   " cells in [1, 100000]" : "a length > 0 (m)")
                << exit(FatalIOError);
        }
        const bool allowed =
            isCount
          ? value >= 1 && value <= 100000 && value == std::floor(value)
          : value > 0 && value < GREAT;
        if (!allowed)
        {
            FatalIOErrorInFunction(bed)
                << "Entry '" << key << "' = " << value << " in"
                << " system/bedGeometry is outside the allowed range "
                << (isCount ? "[1, 100000], a whole number of cells"
                   : "(0, inf), a length in m")
                << exit(FatalIOError);
        }
        if (!isCount) value *= scale;
        // The mesh points may be written with 6 digits (OpenFOAM's default
        // writePrecision): agreement to 1e-5 is a match
        if (mag(value - meshValues[k]) > 1e-5*mag(meshValues[k]))
        {
            differences
                << (differences.str().empty() ? "" : ", ") << key << ' ';
            if (found)
            {
                differences << value;
            }
            else
            {
                differences << "absent (1)";
            }
            differences << " there, " << meshValues[k] << " in the mesh";
        }
    }
    if (!differences.str().empty())
    {
        FatalIOErrorInFunction(bed)
            << "system/bedGeometry does not match the mesh (constant/polyMesh): "
            << differences.str().c_str() << ". Run blockMesh after editing"
            << " system/bedGeometry (blockMeshDict makes the mesh from it)"
            << exit(FatalIOError);
    }
}


// ************************************************************************* //
