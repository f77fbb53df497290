// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The state writers' named points (dem/WritePoints.hpp), in both engines: at each point
// the files on disk are as the header states, so that a process killed there leaves
// exactly that. At "stateWrite.part" the temporary is a strict prefix of the finished
// file, refused by load() as truncated; at "stateWrite.rename" it is the finished file;
// at both the earlier state under the name is untouched.

#include "TestHelpers.hpp"
#include "dem/WritePoints.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace dem;
using namespace dem::test;

namespace {

namespace fs = std::filesystem;

/// What the hook saw at one point: the bytes of the temporary and of the file's name.
struct Seen {
    std::string point, temporary, named;
};

std::string savedPath;
std::vector<Seen> seen;

void record(const char* point)
{
    seen.push_back({point, readBytes(savedPath + ".tmp"), readBytes(savedPath)});
}

Settings engineSettings(int dimension)
{
    Settings s = paperSettings({0.0, 0.02, 0.0, 0.04});
    s.gravity[1] = -9.81;
    s.dimension = dimension;
    if (dimension == 3) s.slabDepth = 0.0075;
    return s;
}

void checkPoints(int dimension)
{
    Simulation sim(engineSettings(dimension));
    const std::vector<int> counts = dimension == 3 ? std::vector<int>{120, 40}
                                                   : std::vector<int>{40, 12};
    sim.packRandom(counts, {0.0, 0.02, 0.0, 0.015}, 5);
    sim.settle(0.1, 0.0);    // landed: the contact lists are not empty
    EXPECT_GT(sim.contactCount(), 0u);
    savedPath = testing::TempDir() + "demWritePoints" + std::to_string(dimension) + ".state";
    sim.save(savedPath);
    const std::string earlier = readBytes(savedPath);
    sim.advance(1e-3);

    seen.clear();
    const WritePointHook before = setWritePointHook(record);
    EXPECT_EQ(before, nullptr);   // none by default
    sim.save(savedPath);
    EXPECT_EQ(setWritePointHook(nullptr), record);
    const std::string finished = readBytes(savedPath);

    ASSERT_EQ(seen.size(), 2u);
    EXPECT_EQ(seen[0].point, "stateWrite.part");
    EXPECT_EQ(seen[1].point, "stateWrite.rename");
    for (const Seen& s : seen) EXPECT_EQ(s.named, earlier) << s.point;

    const std::string& part = seen[0].temporary;
    EXPECT_GT(part.size(), 0u);
    EXPECT_LT(part.size(), finished.size());
    EXPECT_EQ(finished.compare(0, part.size(), part), 0) << "not a prefix";
    const std::string copy = savedPath + ".part";
    std::ofstream(copy, std::ios::binary) << part;
    Simulation reader(engineSettings(dimension));
    try {
        reader.load(copy);
        ADD_FAILURE() << "a part-written state was read";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(copy), std::string::npos) << e.what();
    }

    EXPECT_EQ(seen[1].temporary, finished);
    EXPECT_FALSE(fs::exists(savedPath + ".tmp"));

    sim.save(savedPath);   // no hook: no call
    EXPECT_EQ(seen.size(), 2u);
    fs::remove(savedPath);
    fs::remove(copy);
}

} // namespace

TEST(WritePoints, DiscStateFilesAtEachPoint) { checkPoints(2); }

TEST(WritePoints, SlabStateFilesAtEachPoint) { checkPoints(3); }
