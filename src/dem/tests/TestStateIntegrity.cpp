// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A state is checked on load: a flipped bit, 4 kB zeroed, bytes appended or a cut-short file
// are refused by the checksum and end marker, naming the file and the damage; a state of the
// other engine is named as such; a particle that is not finite, outside the box or on top
// of another is refused naming it.

#include "StateIntegrity.hpp"
#include "TestHelpers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

using namespace dem;
using namespace dem::test;

namespace {

const Box box{0.0, 0.03, 0.0, 0.1};

Settings discSettings()
{
    Settings s = paperSettings(box);
    s.gravity[1] = -9.81;
    return s;
}

Settings slabSettings()
{
    Settings s = discSettings();
    s.dimension = 3;
    s.slabDepth = 0.0075;
    return s;
}

std::string fileName(const std::string& tag)
{
    return ::testing::TempDir() + "stateIntegrity_" + tag + ".state";
}

/// A saved state of particles packed at random and stepped a little (contacts, history).
std::string savedState(const Settings& s, const std::string& tag)
{
    Simulation sim(s);
    sim.packRandom({120, 40}, {0.0, 0.03, 0.0, 0.06}, 7);
    sim.settle(0.002, 0.0);
    const std::string path = fileName(tag);
    sim.save(path);
    return path;
}

/// The checksum written anew, as a file edited on purpose would have it (so that only the
/// particle checks can find the fault).
void resign(std::string& bytes)
{
    const std::size_t at = bytes.size() - 16 - 8;
    const std::uint64_t hash = fnv1a64(bytes.data(), at);
    std::memcpy(&bytes[at], &hash, sizeof(hash));
}

/// Offset of particle i's x in the file: the first array of the particles (length n, then n
/// doubles), found by the positions the simulation holds.
std::size_t xOffset(const std::string& bytes, const Simulation& sim, std::size_t i)
{
    std::string pattern(sizeof(std::uint64_t) + 2 * sizeof(double), '\0');
    const std::uint64_t n = sim.size();
    std::memcpy(&pattern[0], &n, sizeof(n));
    std::memcpy(&pattern[8], &sim.x()[0], sizeof(double));
    std::memcpy(&pattern[16], &sim.x()[1], sizeof(double));
    const std::size_t at = bytes.find(pattern);
    EXPECT_NE(at, std::string::npos);
    return at + 8 + 8 * i;
}

void setDouble(std::string& bytes, std::size_t at, double v) { std::memcpy(&bytes[at], &v, 8); }

std::string loadError(const Settings& s, const std::string& path)
{
    Simulation sim(s);
    try {
        sim.load(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

} // namespace

TEST(StateIntegrity, TheRunRecordIsKeptWithTheState)
{
    for (const Settings& s : {discSettings(), slabSettings()}) {
        Simulation sim(s);
        sim.packRandom({120, 40}, {0.0, 0.03, 0.0, 0.06}, 7);
        sim.setRunRecord("dragModel Beetstra\nformulation A\n");
        const std::string path = fileName("record" + std::to_string(s.dimension));
        sim.save(path);
        Simulation again(s);
        again.load(path);
        EXPECT_EQ(again.runRecord(), "dragModel Beetstra\nformulation A\n");
    }
}

TEST(StateIntegrity, FnvOfKnownTexts)
{
    // Reference values of 64-bit FNV-1a (Fowler, Noll, Vo; IETF draft-eastlake-fnv).
    EXPECT_EQ(fnv1a64("", 0), 0xcbf29ce484222325ULL);
    EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cULL);
    EXPECT_EQ(fnv1a64("foobar", 6), 0x85944171f73967e8ULL);
}

TEST(StateIntegrity, DamagedFilesAreRefusedNamingTheDamage)
{
    for (const Settings& s : {discSettings(), slabSettings()}) {
        const std::string path = savedState(s, "damaged" + std::to_string(s.dimension));
        const std::string good = readBytes(path);
        ASSERT_GT(good.size(), 3u * 4096u);
        EXPECT_EQ(loadError(s, path), "");

        std::string flipped = good;
        flipped[good.size() / 2] ^= 0x10;
        writeBytes(path, flipped);
        std::string e = loadError(s, path);
        EXPECT_TRUE(has(e, path) && has(e, "damaged: its checksum does not match")) << e;

        std::string zeroed = good;
        std::memset(&zeroed[good.size() / 3], 0, 4096);
        writeBytes(path, zeroed);
        e = loadError(s, path);
        EXPECT_TRUE(has(e, path) && has(e, "damaged: its checksum does not match")) << e;

        writeBytes(path, good + "some garbage\n");
        e = loadError(s, path);
        EXPECT_TRUE(has(e, path) && has(e, "damaged: 13 bytes follow its end")) << e;

        writeBytes(path, good.substr(0, good.size() - 5000));
        e = loadError(s, path);
        EXPECT_TRUE(has(e, path) && has(e, "damaged: it does not end with its checksum")) << e;
    }
}

TEST(StateIntegrity, ADamagedVersionFieldOrEndMarkerIsNamedAsDamage)
{
    // The checksum covers the version field: a bit flipped there (to a version that the
    // converter reads, sealed or not) is damage, not an older file; an end marker overwritten
    // in a file of full length is damage, not a cut
    for (const Settings& s : {discSettings(), slabSettings()}) {
        const std::string path = savedState(s, "version" + std::to_string(s.dimension));
        const std::string good = readBytes(path);
        std::uint32_t version = 0;
        std::memcpy(&version, &good[16], sizeof(version));
        for (std::uint32_t bit : {1u, 4u, 64u}) {
            std::string flipped = good;
            const std::uint32_t other = version ^ bit;
            std::memcpy(&flipped[16], &other, sizeof(other));
            writeBytes(path, flipped);
            const std::string e = loadError(s, path);
            EXPECT_TRUE(has(e, path) && has(e, "damaged: its version field reads " + std::to_string(other))
                        && !has(e, "convert")) << e;
        }
        std::string marker = good;
        marker[good.size() - 3] ^= 0x01;
        writeBytes(path, marker);
        std::string e = loadError(s, path);
        EXPECT_TRUE(has(e, path) && has(e, "damaged: its end marker is overwritten (1 of its 16")
                    && has(e, "contents before it intact") && !has(e, "truncated")) << e;
        std::string zeroed = good;
        std::memset(&zeroed[good.size() - 16], 0, 16);
        writeBytes(path, zeroed);
        e = loadError(s, path);
        EXPECT_TRUE(has(e, "damaged: its end marker is overwritten") && !has(e, "truncated")) << e;
        std::remove(path.c_str());
    }
}

TEST(StateIntegrity, TheOtherEnginesStateIsNamed)
{
    const std::string slab = savedState(slabSettings(), "foreignSlab");
    const std::string disc = savedState(discSettings(), "foreignDisc");
    Simulation inPlane(discSettings());
    try {
        inPlane.load(slab);
        ADD_FAILURE() << "a slab state loaded in 2D";
    } catch (const ForeignStateError& e) {
        EXPECT_EQ(e.fileDimension(), 3);
        EXPECT_TRUE(has(e.what(), slab) && has(e.what(), "is a slab state (3D spheres)")) << e.what();
    }
    Simulation inSlab(slabSettings());
    try {
        inSlab.load(disc);
        ADD_FAILURE() << "a 2D state loaded in the slab";
    } catch (const ForeignStateError& e) {
        EXPECT_EQ(e.fileDimension(), 2);
        EXPECT_TRUE(has(e.what(), disc) && has(e.what(), "is a 2D state (discs in a plane)")) << e.what();
    }
}

TEST(StateIntegrity, BadParticlesAreRefusedNamingThem)
{
    for (const Settings& s : {discSettings(), slabSettings()}) {
        const std::string path = savedState(s, "particles" + std::to_string(s.dimension));
        Simulation sim(s);
        sim.load(path);
        const std::string good = readBytes(path);

        std::string bytes = good;
        setDouble(bytes, xOffset(good, sim, 5), std::numeric_limits<double>::quiet_NaN());
        resign(bytes);
        writeBytes(path, bytes);
        std::string e = loadError(s, path);
        EXPECT_TRUE(has(e, path) && has(e, "particle 5 has a position that is not a finite number")) << e;

        bytes = good;
        setDouble(bytes, xOffset(good, sim, 9), box.xMax + 0.001);
        resign(bytes);
        writeBytes(path, bytes);
        e = loadError(s, path);
        EXPECT_TRUE(has(e, "particle 9 at (0.031,") && has(e, "is outside the box [0, 0.03] x [0, 0.1]")) << e;

        // Particle 1 moved onto particle 0 (x and y; in the slab z stays, so put it on 0's z too).
        bytes = good;
        const std::size_t n = sim.size();
        const std::size_t x1 = xOffset(good, sim, 1);
        const std::size_t stride = 8 * n + 8;   // one array: its length, then n doubles
        for (int axis = 0; axis < s.dimension; ++axis) {
            double v0;
            std::memcpy(&v0, &good[x1 - 8 + axis * stride], 8);
            setDouble(bytes, x1 + axis * stride, v0);
        }
        resign(bytes);
        writeBytes(path, bytes);
        e = loadError(s, path);
        EXPECT_TRUE(has(e, "particles 0 at") && has(e, "and 1 at")
                    && has(e, "closer than half the sum of their radii")) << e;
    }
}
