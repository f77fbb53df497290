// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Beds carry what they were made for: a saved bed records its recipe (counts,
// packing region, seed, settling), a bed made otherwise is refused with the entry that
// differs named, state-file mismatches name the setting, and a failed write names the file
// and the OS reason and leaves an earlier state whole.

#include "TestHelpers.hpp"
#include "dem/StateConversion.hpp"
#include "dem/StateRecord.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

using namespace dem;
using namespace dem::test;

namespace {

const Box box{0.0, 0.03, 0.0, 0.1};

Settings settings()
{
    Settings s = paperSettings(box);
    s.gravity[1] = -9.81;
    return s;
}

/// A packed bed saved to `path`.
void saveBed(const std::string& path, const BedRecipe& r = smallBedRecipe())
{
    Simulation sim(settings());
    sim.packBed(r);
    sim.save(path);
}

} // namespace

TEST(BedRecord, SameRecipeLoadsTheBed)
{
    const std::string path = tempPath("bedSame.state");
    Simulation made(settings());
    made.packBed(smallBedRecipe());
    made.save(path);

    Simulation used(settings());
    EXPECT_TRUE(used.loadBed(path, smallBedRecipe()));
    ASSERT_EQ(used.size(), 160u);
    EXPECT_EQ(std::memcmp(used.y(), made.y(), used.size() * sizeof(double)), 0);
    ASSERT_NE(used.recipe(), nullptr);
    EXPECT_EQ(used.recipe()->seed, 42u);
    std::remove(path.c_str());
}

TEST(BedRecord, AnotherCountIsNamed)
{
    const std::string path = tempPath("bedCount.state");
    saveBed(path);
    BedRecipe other = smallBedRecipe();
    other.countPerClass[0] = 200;
    Simulation sim(settings());
    const std::string what = errorOf([&] { sim.loadBed(path, other); });
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("class 'small' count = 120 in the file, 200 here"), std::string::npos)
        << what;
    EXPECT_EQ(what.find("class 'large'"), std::string::npos) << what;
    EXPECT_EQ(sim.size(), 0u);   // untouched
    std::remove(path.c_str());
}

TEST(BedRecord, AnotherSeedSettlingOrRegionIsNamed)
{
    const std::string path = tempPath("bedSeed.state");
    saveBed(path);
    BedRecipe seed = smallBedRecipe();
    seed.seed = 7;
    Simulation sim(settings());
    std::string what = errorOf([&] { sim.loadBed(path, seed); });
    EXPECT_NE(what.find("seed = 42 in the file, 7 here"), std::string::npos) << what;

    BedRecipe settle = smallBedRecipe();
    settle.settleTime = 0.003;
    what = errorOf([&] { sim.loadBed(path, settle); });
    EXPECT_NE(what.find("settle time = 0.002 s in the file, 0.003 s here"), std::string::npos)
        << what;

    BedRecipe region = smallBedRecipe();
    region.region.yMax = 0.05;
    what = errorOf([&] { sim.loadBed(path, region); });
    EXPECT_NE(what.find("packing region = [0, 0.03] x [0, 0.04] m in the file, "
                        "[0, 0.03] x [0, 0.05] m here"),
              std::string::npos)
        << what;

    // Every difference at once, not only the first.
    BedRecipe both = seed;
    both.countPerClass[1] = 41;
    what = errorOf([&] { sim.loadBed(path, both); });
    EXPECT_NE(what.find("class 'large' count = 40 in the file, 41 here; seed = 42"),
              std::string::npos)
        << what;
    std::remove(path.c_str());
}

TEST(BedRecord, AnotherDiameterIsNamed)
{
    const std::string path = tempPath("bedDiameter.state");
    saveBed(path);
    Settings s = settings();
    s.classes[0].diameter = 1.6e-3;
    Simulation sim(s);
    const std::string what = errorOf([&] { sim.loadBed(path, smallBedRecipe()); });
    EXPECT_NE(what.find("other settings: class 'small' diameter = 0.0015 in the file, 0.0016 here"),
              std::string::npos)
        << what;
    std::remove(path.c_str());
}

TEST(BedRecord, RestartMismatchNamesTheSetting)
{
    // A restart state (no recipe needed) read with changed settings.
    const std::string path = tempPath("restartMismatch.state");
    saveBed(path);
    Settings s = settings();
    s.contact.restitution = 0.9;
    s.dt = 2e-5;
    Simulation sim(s);
    std::string what = errorOf([&] { sim.load(path); });
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("contact restitution = 0.97 in the file, 0.9 here; DEM step dt = 1e-05 "
                        "in the file, 2e-05 here"),
              std::string::npos)
        << what;

    Settings three = settings();
    three.classes.push_back({"medium", 2e-3, rho});
    Simulation sim3(three);
    what = errorOf([&] { sim3.load(path); });
    EXPECT_NE(what.find("number of size classes = 2 in the file, 3 here"), std::string::npos)
        << what;

    // The recipe goes on with the particles into restart states.
    Simulation same(settings());
    same.load(path);
    ASSERT_NE(same.recipe(), nullptr);
    EXPECT_EQ(same.recipe()->countPerClass, smallBedRecipe().countPerClass);
    std::remove(path.c_str());
}

TEST(BedRecord, ConvertedVersionThreeBedIsCheckedOnItsCounts)
{
    // A version-3 file (before beds recorded their recipe), converted: the version-9 layout
    // without the run record (after the version), the checksum (before the end marker), the
    // key's contact entries of version 7, the recipe flag and the step of the last list
    // build (after the step count and the build count).
    const std::string path = tempPath("bedVersion3.state");
    Simulation sim(settings());
    sim.packRandom(smallBedRecipe().countPerClass, smallBedRecipe().region, 42);
    EXPECT_EQ(sim.recipe(), nullptr);
    sim.save(path);
    std::string bytes = readBytes(path);
    bytes.erase(bytes.size() - 24, 8);
    std::uint64_t recordLength;
    std::memcpy(&recordLength, &bytes[20], sizeof(recordLength));
    bytes.erase(20, 8 + recordLength);
    const std::uint32_t three = 3;
    std::memcpy(&bytes[16], &three, sizeof(three));
    std::uint64_t keyLength;
    std::memcpy(&keyLength, &bytes[20], sizeof(keyLength));
    // The key without the contact law, tangential damping ratio, rolling friction, the walls'
    // moduli and the 2 classes' moduli (version 7), which sit before its last entry
    const std::size_t added = 6 + 2 * 2;
    bytes.erase(28 + (keyLength - 1 - added) * sizeof(double), added * sizeof(double));
    keyLength -= added;
    std::memcpy(&bytes[20], &keyLength, sizeof(keyLength));
    const std::size_t flag = 28 + keyLength * sizeof(double);
    ASSERT_EQ(bytes[flag], 0);
    bytes.erase(flag + 1 + 2 * sizeof(std::int64_t), sizeof(std::int64_t));
    bytes.erase(flag, 1);
    writeBytes(path, bytes);
    convertState(path, path);

    Simulation old(settings());
    EXPECT_FALSE(old.loadBed(path, smallBedRecipe()));   // counts match: read, not fully checked
    EXPECT_EQ(old.size(), 160u);
    EXPECT_EQ(old.recipe(), nullptr);

    BedRecipe other = smallBedRecipe();
    other.countPerClass = {600, 130};
    Simulation refused(settings());
    const std::string what = errorOf([&] { refused.loadBed(path, other); });
    EXPECT_NE(what.find("class 'small' count = 120 in the file, 600 here; class 'large' count = "
                        "40 in the file, 130 here"),
              std::string::npos)
        << what;
    std::remove(path.c_str());
}

TEST(BedRecord, PackBedNeedsAnEmptySimulation)
{
    Simulation sim(settings());
    sim.addParticle(0, 0.01, 0.01);
    const std::string what = errorOf([&] { sim.packBed(smallBedRecipe()); });
    EXPECT_NE(what.find("particles already"), std::string::npos) << what;

    // A particle added to a packed bed: the recipe no longer describes it.
    Simulation packed(settings());
    packed.packBed(smallBedRecipe());
    ASSERT_NE(packed.recipe(), nullptr);
    packed.addParticle(0, 0.015, 0.095);
    EXPECT_EQ(packed.recipe(), nullptr);
}

TEST(BedRecord, FailedWriteNamesFileAndReasonAndKeepsTheEarlierState)
{
    namespace fs = std::filesystem;
    const std::string dir = tempPath("bedWrite");
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string path = dir + "/bed.state";
    saveBed(path);
    const std::string before = readBytes(path);

    // The temporary cannot be created (a directory is in its place).
    fs::create_directory(path + ".tmp");
    Simulation other(settings());
    other.packBed([] { BedRecipe r = smallBedRecipe(); r.seed = 3; return r; }());
    std::string what = errorOf([&] { other.save(path); });
    EXPECT_NE(what.find("cannot write state file '" + path + "'"), std::string::npos) << what;
    EXPECT_NE(what.find("Is a directory"), std::string::npos) << what;
    EXPECT_EQ(readBytes(path), before);
    fs::remove(path + ".tmp");

    // The target is a directory: the rename fails, no stray temporary is left.
    const std::string intoDir = dir + "/aDirectory";
    fs::create_directory(intoDir);
    what = errorOf([&] { other.save(intoDir); });
    EXPECT_NE(what.find("cannot write state file '" + intoDir + "'"), std::string::npos) << what;
    EXPECT_FALSE(fs::exists(intoDir + ".tmp"));

    // A parent that is a regular file.
    what = errorOf([&] { other.save(path + "/sub/bed.state"); });
    EXPECT_NE(what.find("cannot write state file '" + path + "/sub/bed.state'"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("ot a directory"), std::string::npos) << what;

    // Missing parent directories are made.
    other.save(dir + "/new/deeper/bed.state");
    EXPECT_TRUE(fs::is_regular_file(dir + "/new/deeper/bed.state"));
    fs::remove_all(dir);
}

TEST(BedRecord, CheckStatePathWritesNothing)
{
    namespace fs = std::filesystem;
    const std::string dir = tempPath("bedCheckPath");
    fs::remove_all(dir);
    fs::create_directories(dir);

    std::string what = errorOf([&] { checkStatePath(dir); });
    EXPECT_NE(what.find("'" + dir + "': it is a directory"), std::string::npos) << what;

    const std::string file = dir + "/aFile";
    writeBytes(file, "x");
    what = errorOf([&] { checkStatePath(file + "/bed.state"); });
    EXPECT_NE(what.find("'" + file + "' is not a directory"), std::string::npos) << what;

    EXPECT_EQ(errorOf([&] { checkStatePath(dir + "/missing/bed.state"); }), "");
    EXPECT_EQ(errorOf([&] { checkStatePath(dir + "/bed.state"); }), "");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);

    what = errorOf([&] { checkStatePath("/proc/bed.state"); });
    EXPECT_NE(what.find("cannot write state file '/proc/bed.state': cannot create a file in "
                        "'/proc'"),
              std::string::npos)
        << what;
    fs::remove_all(dir);
}

TEST(BedRecord, CloseValuesPrintApart)
{
    using Texts = std::pair<std::string, std::string>;
    EXPECT_EQ(textsApart(0.0849211764173491, 0.0760854470791278), Texts("0.0849212", "0.0760854"));
    EXPECT_EQ(textsApart(1e-5, 2e-5), Texts("1e-05", "2e-05"));
    const Texts close = textsApart(0.1 + 0.2, 0.3);
    EXPECT_NE(close.first, close.second);
}

TEST(BedRecord, SettlingReportsItsProgressWithoutChangingTheBed)
{
    // Checked every 100 steps: 0.005 s at dt = 1e-5 s is 500 steps, so 5 reports at
    // 0, 1, ..., 4 ms (no energy tolerance: the whole settling time runs).
    BedRecipe r = smallBedRecipe();
    r.settleTime = 0.005;
    ASSERT_DOUBLE_EQ(settings().dt, 1e-5);
    std::vector<double> times, energies;
    Simulation reported(settings());
    reported.packBed(r, [&](double t, double ke) {
        times.push_back(t);
        energies.push_back(ke);
    });
    ASSERT_EQ(times.size(), 5u);
    for (std::size_t k = 0; k < times.size(); ++k) EXPECT_DOUBLE_EQ(times[k], 1e-3 * k);

    // The same bed without a report, to the bit.
    Simulation silent(settings());
    silent.packBed(r);
    ASSERT_EQ(silent.size(), reported.size());
    EXPECT_EQ(std::memcmp(silent.y(), reported.y(), silent.size() * sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(silent.vy(), reported.vy(), silent.size() * sizeof(double)), 0);

    // The energy reported at 3 ms is that of the same packing settled for 3 ms.
    Simulation shorter(settings());
    shorter.packRandom(r.countPerClass, r.region, r.seed);
    shorter.settle(0.003, 0.0);
    EXPECT_EQ(energies[3], shorter.kineticEnergy() / static_cast<double>(shorter.size()));
    EXPECT_GT(energies[3], 0.0);
}

// A mesh of other cell counts gives the same box to a last digit (blockMesh sums its cells:
// 0.15000000000000002 against 0.15): the bed loads; a box 1e-9 apart is another bed.
TEST(BedRecord, BoxApartByRoundOffLoadsTheBed)
{
    const std::string path = tempPath("bedRoundOff.state");
    saveBed(path);
    Settings nearly = settings();
    nearly.box.xMax = std::nextafter(box.xMax, 1.0);
    nearly.box.yMax = std::nextafter(nearly.box.yMax, 0.0);
    BedRecipe r = smallBedRecipe();
    r.region.xMax = nearly.box.xMax;
    Simulation used(nearly);
    EXPECT_TRUE(used.loadBed(path, r));
    EXPECT_EQ(used.size(), 160u);

    Settings other = settings();
    other.box.xMax = box.xMax * (1 + 1e-9);
    BedRecipe wider = smallBedRecipe();
    wider.region.xMax = other.box.xMax;
    Simulation refused(other);
    const std::string what = errorOf([&] { refused.loadBed(path, wider); });
    EXPECT_NE(what.find("box xMax"), std::string::npos) << what;
    std::remove(path.c_str());
}
