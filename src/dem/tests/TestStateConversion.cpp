// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The engines read their current state version only; an older file is refused naming its
// version and the command that converts it, and dpmConvertState writes it in the current
// version. The older files are made here from a current one by the layout changes of each
// version (StateConversion.cpp): the converted file must be the current writer's bytes for
// the same particles, with what the older version did not carry as the converter documents
// (2D before 7 and slab before 5: the settings key's contact law, tangential damping, rolling
// friction and moduli as those versions ran, the law of the run record else linear; 2D
// before 6 and slab before 4: no run record; 2D before 5 and slab before 3: the skin's clock
// at the file's step; 2D before 4 and slab 1: no recipe; 2D 2: the list built anew; slab
// before 3: skin 0.1 d_min).

#include "OlderStateFiles.hpp"
#include "StateIntegrity.hpp"
#include "TestHelpers.hpp"
#include "dem/SlabSystem.hpp"
#include "dem/StateConversion.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace dem;
using namespace dem::test;

namespace {

const Box box{0.0, 0.03, 0.0, 0.1};

Settings settingsOf(int dimension)
{
    Settings s = paperSettings(box);
    s.gravity[1] = -9.81;
    if (dimension == 3) {
        s.dimension = 3;
        s.slabDepth = 0.0075;
    }
    return s;
}

std::string fileName(const std::string& tag)
{
    return ::testing::TempDir() + "stateConversion_" + tag + ".state";
}

/// A packed bed (with its recipe), stepped a little: contacts, history, a list in groups.
std::string savedBed(int dimension, const std::string& path)
{
    Simulation sim(settingsOf(dimension));
    const BedRecipe r = smallBedRecipe();
    sim.packBed(r);
    sim.advance(0.0005);
    sim.save(path);
    return readBytes(path);
}


bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

} // namespace

TEST(StateConversion, EveryOlderDiscVersionBecomesTheCurrentWritersBytes)
{
    const std::string current = fileName("disc");
    const std::string b = savedBed(2, current);
    ASSERT_EQ(get<std::uint32_t>(b, 16), discStateVersion);
    ASSERT_EQ(b[Layout(b, 2).recipe], 1);   // a recipe to carry over (versions 4, 5)
    for (std::uint32_t version = oldestDiscStateVersion; version < discStateVersion; ++version) {
        SCOPED_TRACE("2D version " + std::to_string(version));
        std::string expected;
        const std::string old = fileName("disc" + std::to_string(version));
        const std::string converted = old + ".converted";
        writeBytes(old, olderDisc(b, version, expected));

        // Refused by the engine, naming the version and the command
        Simulation refused(settingsOf(2));
        const std::string e = errorOf([&] { refused.load(old); });
        EXPECT_TRUE(has(e, "state file '" + old + "' is of version " + std::to_string(version)
                           + ", older than this build reads (9): convert it with 'dpmConvertState "
                           + old + "'"))
            << e;

        const StateConversion c = convertState(old, converted);
        EXPECT_EQ(c.dimension, 2);
        EXPECT_EQ(c.fromVersion, version);
        EXPECT_EQ(c.toVersion, discStateVersion);
        EXPECT_TRUE(readBytes(converted) == expected);
        if (version == discStateVersion - 1) {
            EXPECT_TRUE(expected == b);   // nothing missing
        }

        Simulation sim(settingsOf(2));
        ASSERT_NO_THROW(sim.load(converted));
        EXPECT_EQ(sim.size(), 160u);
        EXPECT_EQ(sim.recipe() != nullptr, version >= 4);
    }
}

TEST(StateConversion, EveryOlderSlabVersionBecomesTheCurrentWritersBytes)
{
    const std::string current = fileName("slab");
    const std::string b = savedBed(3, current);
    ASSERT_EQ(get<std::uint32_t>(b, 16), slabStateVersion);
    for (std::uint32_t version = oldestSlabStateVersion; version < slabStateVersion; ++version) {
        SCOPED_TRACE("slab version " + std::to_string(version));
        std::string expected;
        const std::string old = fileName("slab" + std::to_string(version));
        const std::string converted = old + ".converted";
        writeBytes(old, olderSlab(b, version, expected, dSmall));

        Simulation refused(settingsOf(3));
        const std::string e = errorOf([&] { refused.load(old); });
        EXPECT_TRUE(has(e, "slab state file '" + old + "' is of version " + std::to_string(version)
                           + ", older than this build reads (7): convert it with 'dpmConvertState "
                           + old + "'"))
            << e;

        const StateConversion c = convertState(old, converted);
        EXPECT_EQ(c.dimension, 3);
        EXPECT_EQ(c.fromVersion, version);
        EXPECT_TRUE(readBytes(converted) == expected);
        if (version == slabStateVersion - 1) {
            EXPECT_TRUE(expected == b);
        }
        EXPECT_EQ(has(c.notes, "0.1 d_min = 0.00015 m"), version <= 2) << c.notes;

        Simulation sim(settingsOf(3));
        ASSERT_NO_THROW(sim.load(converted));
        EXPECT_EQ(sim.size(), 160u);
        EXPECT_EQ(sim.recipe() != nullptr, version >= 2);
    }
}

TEST(StateConversion, CurrentUnknownAndForeignFilesAreNamed)
{
    const std::string current = fileName("current");
    const std::string b = savedBed(2, current);
    const std::string out = fileName("notWritten");
    std::remove(out.c_str());
    const StateConversion c = convertState(current, out);
    EXPECT_EQ(c.fromVersion, discStateVersion);
    EXPECT_EQ(c.toVersion, discStateVersion);
    EXPECT_FALSE(std::filesystem::exists(out));

    // A whole file of a version this build does not know (its checksum its own); with the
    // checksum of version 9 it is a damaged field (TestStateIntegrity)
    std::string unknown = b;
    put(unknown, 16, std::uint32_t{10});
    put(unknown, unknown.size() - 24, fnv1a64(unknown.data(), unknown.size() - 24));
    writeBytes(current, unknown);
    EXPECT_TRUE(has(errorOf([&] { convertState(current, out); }),
                    "state file '" + current + "' is not a valid DEM state: 2D state version 10, "
                    "expected 2 to 9"));
    Simulation sim(settingsOf(2));
    EXPECT_TRUE(has(errorOf([&] { sim.load(current); }),
                    "state file '" + current + "' is not a valid DEM state: version 10, expected 9"));

    writeBytes(current, "a bed of particles, in words");
    EXPECT_TRUE(has(errorOf([&] { convertState(current, out); }), "wrong file type"));

    // An older file cut short: named, nothing written
    std::string expected;
    std::string old = olderDisc(b, 5, expected);
    writeBytes(current, old.substr(0, old.size() / 2));
    EXPECT_TRUE(has(errorOf([&] { convertState(current, out); }),
                    "state file '" + current + "' is not a valid DEM state: "));
    EXPECT_FALSE(std::filesystem::exists(out));
}

// The command: in place, the original kept beside it; its usage without arguments.
TEST(StateConversion, TheCommandConvertsInPlaceAndKeepsTheOriginal)
{
    const std::string b = savedBed(2, fileName("command"));
    std::string expected;
    const std::string old = olderDisc(b, 3, expected);
    const std::string path = fileName("command3");
    writeBytes(path, old);
    const std::string log = path + ".log";
    const std::string command = std::string(DEM_CONVERT_STATE) + " " + path + " >" + log + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << readBytes(log);
    EXPECT_TRUE(readBytes(path) == expected);
    EXPECT_TRUE(readBytes(path + ".version3") == old);
    const std::string said = readBytes(log);
    EXPECT_TRUE(has(said, "Converted '" + path + "' (2D state version 3) to '" + path
                          + "' (version 9)")
                && has(said, "Note: it carries no checksum: its integrity could not be checked"))
        << said;

    const std::string usage = std::string(DEM_CONVERT_STATE) + " >" + log + " 2>&1";
    EXPECT_NE(std::system(usage.c_str()), 0);
    EXPECT_TRUE(has(readBytes(log), "Usage: dpmConvertState <in> [<out>]")) << readBytes(log);

    const std::string missing = std::string(DEM_CONVERT_STATE) + " " + path + ".none >" + log + " 2>&1";
    EXPECT_NE(std::system(missing.c_str()), 0);
    EXPECT_TRUE(has(readBytes(log), "dpmConvertState: cannot open state file '" + path + ".none'"))
        << readBytes(log);
}

TEST(StateConversion, InPlaceWithABackupNameThatIsADirectoryIsRefusedCleanly)
{
    // The original's backup name taken by a directory: a clear error naming it, the original
    // unchanged and no temporary left beside it
    const std::string b = savedBed(2, fileName("backupDir"));
    std::string expected;
    const std::string old = olderDisc(b, 3, expected);
    const std::string path = fileName("backupDir3");
    writeBytes(path, old);
    std::filesystem::remove_all(path + ".version3");
    std::filesystem::create_directory(path + ".version3");
    const std::string log = path + ".log";
    const std::string command = std::string(DEM_CONVERT_STATE) + " " + path + " >" + log + " 2>&1";
    EXPECT_NE(std::system(command.c_str()), 0);
    const std::string said = readBytes(log);
    EXPECT_TRUE(has(said, "cannot keep the original '" + path + "' as '" + path + ".version3'")
                && has(said, "is a directory") && has(said, "nothing converted")) << said;
    EXPECT_TRUE(readBytes(path) == old);
    EXPECT_FALSE(std::filesystem::exists(path + ".converting"));
    std::filesystem::remove_all(path + ".version3");
}

// The versions before the contact law in the settings key (2D 6, slab 4) carried a run
// record: the converted file continues with the same bits as the run it was saved from,
// and a run record naming HertzMindlin gives the key that law.
TEST(StateConversion, PreviousVersionContinuesWithTheSameBits)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        const std::uint32_t previous = dimension == 2 ? 6 : 4;
        const std::string path = fileName("continued" + std::to_string(dimension));
        Simulation run(settingsOf(dimension));
        const BedRecipe r = smallBedRecipe();
        run.packBed(r);
        run.advance(0.0005);
        run.setRunRecord("dragModel Beetstra\n");
        run.save(path);
        const std::string b = readBytes(path);
        std::string expected;
        const std::string old = path + ".previous";
        writeBytes(old, dimension == 2 ? olderDisc(b, previous, expected)
                                     : olderSlab(b, previous, expected, dSmall));
        const StateConversion c = convertState(old, old + ".converted");
        EXPECT_TRUE(readBytes(old + ".converted") == b);
        EXPECT_TRUE(has(c.notes, "written as contactLaw linear (the default), "
                                 "tangentialDampingRatio 1, rollingFriction and "
                                 "rollingFrictionWall 0"))
            << c.notes;
        EXPECT_FALSE(has(c.notes, "no checksum")) << c.notes;

        Simulation continued(settingsOf(dimension));
        continued.load(old + ".converted");
        EXPECT_EQ(continued.runRecord(), "dragModel Beetstra\n");
        run.advance(0.0005);
        continued.advance(0.0005);
        const std::size_t n = run.size() * sizeof(double);
        ASSERT_EQ(continued.size(), run.size());
        EXPECT_EQ(std::memcmp(continued.x(), run.x(), n), 0);
        EXPECT_EQ(std::memcmp(continued.y(), run.y(), n), 0);
        EXPECT_EQ(std::memcmp(continued.vx(), run.vx(), n), 0);
        EXPECT_EQ(std::memcmp(continued.vy(), run.vy(), n), 0);
        EXPECT_EQ(std::memcmp(continued.omegaZ(), run.omegaZ(), n), 0);

        // A run record of HertzMindlin: the law kept, a linear run refuses the file
        run.setRunRecord("dragModel Beetstra\ncontactLaw HertzMindlin\n");
        run.save(path);
        const std::string hertz = readBytes(path);
        writeBytes(old, dimension == 2 ? olderDisc(hertz, previous, expected)
                                     : olderSlab(hertz, previous, expected, dSmall));
        const StateConversion h = convertState(old, old + ".converted");
        EXPECT_TRUE(has(h.notes, "written as contactLaw HertzMindlin (its run record's)"))
            << h.notes;
        Simulation linear(settingsOf(dimension));
        const std::string e = errorOf([&] { linear.load(old + ".converted"); });
        EXPECT_TRUE(has(e, "was written with other settings: contact law = HertzMindlin in the "
                           "file, linear here"))
            << e;
    }
}

// A state of the previous version has no coefficients of pairs or walls of their own: it
// loads in a run whose pairs take the global ones, and one with a pair's own is refused
// naming it.
TEST(StateConversion, ConvertedStateIsOfTheGlobalCoefficients)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE("dimension " + std::to_string(dimension));
        const std::uint32_t previous = dimension == 2 ? discStateVersion - 1 : slabStateVersion - 1;
        const std::string path = fileName("global" + std::to_string(dimension));
        const std::string b = savedBed(dimension, path);
        std::string expected;
        const std::string old = path + ".previous";
        writeBytes(old, dimension == 2 ? olderDisc(b, previous, expected)
                                     : olderSlab(b, previous, expected, dSmall));
        convertState(old, old + ".converted");

        Settings same = settingsOf(dimension);
        PairContactSettings p;
        p.classB = 1;
        p.restitution = same.contact.restitution;
        same.contact.pairs = {p};
        Simulation loads(same);
        EXPECT_EQ(errorOf([&] { loads.load(old + ".converted"); }), "");

        Settings own = same;
        own.contact.pairs[0].restitution = 0.8;
        Simulation refused(own);
        const std::string e = errorOf([&] { refused.load(old + ".converted"); });
        EXPECT_TRUE(has(e, "was written with other settings: contact pair 'small-large' "
                           "restitution = 0.97 in the file, 0.8 here"))
            << e;
    }
}
