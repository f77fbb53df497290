// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A bed's settle friction in its record (BedRecipe::settleFriction), in both engines' state
// files: saved and read back, a bed settled otherwise refused naming it, a bad value refused
// before the packing, and a bed of the version before it (settled with the contacts' own)
// converted, read as settled with the contacts' own friction.

#include "OlderStateFiles.hpp"
#include "TestHelpers.hpp"
#include "dem/StateConversion.hpp"
#include "dem/StateRecord.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

using namespace dem;
using namespace dem::test;

namespace {

Settings settingsOf(int dimension)
{
    Settings s = paperSettings({0.0, 0.03, 0.0, 0.1});
    s.gravity[1] = -9.81;
    if (dimension == 3) {
        s.dimension = 3;
        s.slabDepth = 0.0075;
    }
    return s;
}

BedRecipe recipeWith(std::optional<double> settleFriction)
{
    BedRecipe r = smallBedRecipe();
    r.settleFriction = settleFriction;
    return r;
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string engineName(int dimension) { return dimension == 2 ? "2D" : "slab"; }

} // namespace

// Saved with the bed and read back (load and loadBed), and into a restart state after it
TEST(SettleFrictionRecord, RoundTripsThroughTheStateFile)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE(engineName(dimension));
        const std::string path = tempPath("settleFrictionRoundTrip.state");
        Simulation made(settingsOf(dimension));
        made.packBed(recipeWith(0.0));
        ASSERT_NE(made.recipe(), nullptr);
        ASSERT_TRUE(made.recipe()->settleFriction.has_value());
        made.save(path);

        Simulation used(settingsOf(dimension));
        EXPECT_TRUE(used.loadBed(path, recipeWith(0.0)));
        ASSERT_NE(used.recipe(), nullptr);
        ASSERT_TRUE(used.recipe()->settleFriction.has_value());
        EXPECT_EQ(*used.recipe()->settleFriction, 0.0);

        used.advance(0.001);
        used.save(path);
        Simulation restarted(settingsOf(dimension));
        restarted.load(path);
        ASSERT_NE(restarted.recipe(), nullptr);
        EXPECT_EQ(restarted.recipe()->settleFriction, std::optional<double>(0.0));

        // A bed settled with the contacts' own: none recorded
        Simulation plain(settingsOf(dimension));
        plain.packBed(recipeWith(std::nullopt));
        plain.save(path);
        Simulation read(settingsOf(dimension));
        EXPECT_TRUE(read.loadBed(path, recipeWith(std::nullopt)));
        EXPECT_FALSE(read.recipe()->settleFriction.has_value());
        std::remove(path.c_str());
    }
}

// A bed settled with another settle friction, or with the contacts' own where one is asked
// for (and the reverse), is refused naming it; the simulation is left empty
TEST(SettleFrictionRecord, ABedSettledOtherwiseIsRefusedNamingIt)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE(engineName(dimension));
        const std::string zero = tempPath("settleFrictionZero.state");
        const std::string own = tempPath("settleFrictionOwn.state");
        {
            Simulation a(settingsOf(dimension));
            a.packBed(recipeWith(0.0));
            a.save(zero);
            Simulation b(settingsOf(dimension));
            b.packBed(recipeWith(std::nullopt));
            b.save(own);
        }
        struct Case {
            std::string file;
            std::optional<double> here;
            std::string said;
        };
        const Case cases[] = {
            {zero, std::nullopt, "settle friction = 0 in the file, the contacts' own here"},
            {zero, 0.1, "settle friction = 0 in the file, 0.1 here"},
            {own, 0.0, "settle friction = the contacts' own in the file, 0 here"},
        };
        for (const Case& c : cases) {
            Simulation sim(settingsOf(dimension));
            const std::string e = errorOf([&] { sim.loadBed(c.file, recipeWith(c.here)); });
            EXPECT_TRUE(has(e, "bed '" + c.file + "' was made for other particles: " + c.said)) << e;
            EXPECT_EQ(sim.size(), 0u);
        }
        // bedDifferences (a restart's check) names it alike; values told apart
        EXPECT_EQ(bedDifferences(settingsOf(dimension), recipeWith(0.1), recipeWith(0.1 + 1e-9)),
                  "settle friction = 0.1 in the file, 0.100000001 here");
        EXPECT_EQ(bedDifferences(settingsOf(dimension), recipeWith(0.2), recipeWith(0.2)), "");
        std::remove(zero.c_str());
        std::remove(own.c_str());
    }
}

// Negative, not a number or infinite: refused before anything is packed
TEST(SettleFrictionRecord, ABadValueIsRefusedBeforeThePacking)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE(engineName(dimension));
        for (double bad : {-0.1, std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity()}) {
            Simulation sim(settingsOf(dimension));
            const std::string e = errorOf([&] { sim.packBed(recipeWith(bad)); });
            EXPECT_TRUE(has(e, "settle friction = " + formatValue(bad) + " is outside [0, inf)"))
                << e;
            EXPECT_EQ(sim.size(), 0u);
        }
    }
}

// A bed of the version before the settle friction (2D 8, slab 6), converted: the current
// writer's bytes of a bed settled with the contacts' own friction; read as such, and refused
// for a case that asks for a settle friction
TEST(SettleFrictionRecord, AnOlderBedLoadsAsSettledWithTheContactsOwn)
{
    for (int dimension : {2, 3}) {
        SCOPED_TRACE(engineName(dimension));
        const std::string path = tempPath("settleFrictionOlder.state");
        Simulation made(settingsOf(dimension));
        made.packBed(recipeWith(std::nullopt));
        made.save(path);
        const std::string b = readBytes(path);
        const std::uint32_t previous = (dimension == 2 ? discStateVersion : slabStateVersion) - 1;
        std::string expected;
        writeBytes(path, dimension == 2 ? olderDisc(b, previous, expected)
                                        : olderSlab(b, previous, expected, dSmall));
        EXPECT_EQ(get<std::uint32_t>(readBytes(path), 16), previous);
        EXPECT_LT(readBytes(path).size(), b.size());   // 8 bytes fewer: no settle friction

        const StateConversion c = convertState(path, path);
        EXPECT_EQ(c.fromVersion, previous);
        EXPECT_TRUE(readBytes(path) == b);

        Simulation used(settingsOf(dimension));
        EXPECT_TRUE(used.loadBed(path, recipeWith(std::nullopt)));
        ASSERT_NE(used.recipe(), nullptr);
        EXPECT_FALSE(used.recipe()->settleFriction.has_value());

        Simulation asked(settingsOf(dimension));
        const std::string e = errorOf([&] { asked.loadBed(path, recipeWith(0.0)); });
        EXPECT_TRUE(has(e, "settle friction = the contacts' own in the file, 0 here")) << e;
        std::remove(path.c_str());
    }
}

// A record that holds more than one value is a damaged file, named
TEST(SettleFrictionRecord, ARecordOfSeveralValuesIsNotAValidState)
{
    std::optional<double> mu;
    EXPECT_TRUE(settleFrictionOfRecord({}, mu));
    EXPECT_FALSE(mu.has_value());
    EXPECT_TRUE(settleFrictionOfRecord({0.25}, mu));
    EXPECT_EQ(mu, std::optional<double>(0.25));
    EXPECT_FALSE(settleFrictionOfRecord({0.25, 0.5}, mu));
    EXPECT_EQ(settleFrictionRecord(recipeWith(std::nullopt)), std::vector<double>{});
    EXPECT_EQ(settleFrictionRecord(recipeWith(0.3)), std::vector<double>{0.3});
}
