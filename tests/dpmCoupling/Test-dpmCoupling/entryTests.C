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
    Test-dpmCoupling: the unknown-entry check (knownEntries.H): the edit
    distance, and what passes and what does not (GoogleTest suite
    KnownEntries).

\*---------------------------------------------------------------------------*/

#include "couplingTest.H"
#include "knownEntries.H"
#include "IStringStream.H"

using namespace Foam;


// Unknown entries: the edit distance
TEST(KnownEntries, EditDistance)
{
    check("edit distance restitutoin/restitution", editDistance("restitutoin", "restitution"), 2, 0);
    check("edit distance nThread/nThreads", editDistance("nThread", "nThreads"), 1, 0);
    check("edit distance to an empty word", editDistance("", "kn"), 2, 0);
}


// Unknown entries: what passes and what does not
TEST(KnownEntries, UnknownEntryRefusedWithTheNearestName)
{
    const wordList known{"kn", "kt", "restitution"};
    auto message = [&](const string& text)
    {
        IStringStream is(text);
        const dictionary dict(is);
        FatalIOError.throwExceptions();
        try
        {
            checkKnownEntries(dict, known, "contact", wordHashSet{"wSmall"});
        }
        catch (const IOerror& err)
        {
            FatalIOError.dontThrowExceptions();
            return string(err.message());
        }
        FatalIOError.dontThrowExceptions();
        return string();
    };
    check("known entries, a pattern, a settings entry pass", message("kn 1; \"(kt|restitution)\" 0.5; wSmall 0.5;").empty(), 1, 0);
    const string m = message("kn 1; restitutoin 0.9;");
    Info<< "    message: " << m.c_str() << endl;
    check("a misspelling names the nearest entry", m.find("unknown entry 'restitutoin' in contact; did you mean 'restitution'?") != string::npos, 1, 0);
    check("a pattern matching no entry is unknown", message("\"kx.*\" 1;").empty(), 0, 0);
}
