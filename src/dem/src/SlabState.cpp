// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab's state file: everything the next step reads (particles, forces of the last
// evaluation, the neighbour list in its order with the 3-vector histories, the plane walls
// and the wall contacts, the reference positions), so a restart continues bit for bit. The
// walls of Settings::walls, cylinders included, are in the settings key (appendWallsRecord),
// so a state is read with the walls it was made with. A file of its own kind: a 2D state
// and a slab state cannot be mistaken for each other.
// It holds the caller's record of the run (its models, runRecord()), the recipe of a packed
// bed, so that a case starting from it checks every entry of how it was made, the skin and
// the step of the last list build (the adaptive skin's state), and a checksum (64-bit
// FNV-1a of every byte before it) ahead of the end marker.
// Version policy: as the 2D engine's (StateFile.cpp): this version only is written and
// read, an older one (1-6) is refused naming the command that converts it.

#include "RecordCompare.hpp"
#include "SlabWalls.hpp"
#include "StateIntegrity.hpp"
#include "dem/StateConversion.hpp"
#include "dem/SlabSystem.hpp"
#include "dem/StateRecord.hpp"
#include "dem/System.hpp"
#include "dem/WritePoints.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <type_traits>

namespace dem {

namespace {

const char (&slabMagic)[16] = slabStateMagic;
constexpr std::uint32_t slabVersion = slabStateVersion;

std::vector<double> slabKey(const Settings& s)
{
    std::vector<double> key = settingsKey(s, 0.0);
    key.pop_back();   // the skin: a state may continue with another
    key.push_back(s.slabDepth);
    appendWallsRecord(key, s);
    return key;
}

} // namespace

void SlabSystem::save(const std::string& path) const
{
    namespace fs = std::filesystem;
    const fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty()) fs::create_directories(parent, ec);
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("cannot write slab state file '" + tmp + "': " + std::strerror(errno));
        std::uint64_t hash = fnv1a64(nullptr, 0);
        auto bytes = [&](const void* data, std::size_t n) {
            hash = fnv1a64(static_cast<const char*>(data), n, hash);
            out.write(static_cast<const char*>(data), static_cast<std::streamsize>(n));
        };
        auto value = [&](auto v) { bytes(&v, sizeof(v)); };
        auto array = [&](const auto& a) {
            value(static_cast<std::uint64_t>(a.size()));
            bytes(a.data(), a.size() * sizeof(a[0]));
        };
        bytes(slabMagic, sizeof(slabMagic));
        value(slabVersion);
        array(std::vector<char>(runRecord_.begin(), runRecord_.end()));
        array(slabKey(settings_));
        value(static_cast<std::uint8_t>(recipe_.has_value()));
        if (recipe_) {
            array(recipe_->countPerClass);
            value(recipe_->region);
            value(recipe_->seed);
            value(recipe_->settleTime);
            value(recipe_->keTolerance);
            array(placedRecord(*recipe_));
            array(settleFrictionRecord(*recipe_));
        }
        value(stepCount_);
        value(listBuilds_);
        value(skin_);
        value(lastBuildStep_);
        std::vector<double> wallData;
        for (const PlaneWall3& w : walls_) {
            wallData.insert(wallData.end(), {w.point.x(), w.point.y(), w.point.z(),
                                             w.nHat.x(), w.nHat.y(), w.nHat.z()});
        }
        array(wallData);
        p_.forEachArray([&](const auto& a) { array(a); });
        out.flush();
        atWritePoint("stateWrite.part");
        const std::uint8_t ready = listValid_ && forcesValid_;
        value(ready);
        array(pairs_.i); array(pairs_.j); array(pairs_.law); array(pairs_.xi);
        array(pairs_.groupStart);
        array(wallContacts_.start); array(wallContacts_.wall); array(wallContacts_.xi);
        const std::uint64_t checksum = hash;
        value(checksum);
        bytes(slabMagic, sizeof(slabMagic));   // end marker
        out.flush();
        if (!out) {
            std::remove(tmp.c_str());
            throw Error("cannot write slab state file '" + path + "': " + std::strerror(errno));
        }
    }
    atWritePoint("stateWrite.rename");
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        std::remove(tmp.c_str());
        throw Error("cannot rename '" + tmp + "' to '" + path + "': " + std::strerror(errno));
    }
}

void SlabSystem::load(const std::string& path)
{
    const std::string file = readStateBytes(path, "slab state file");
    refuseForeignEngine(file, 3, path);
    auto fail = [&](const std::string& what) {
        throw Error("slab state file '" + path + "' is not a valid slab state: " + what);
    };
    std::size_t at = 0;
    auto bytes = [&](void* to, std::size_t n) {
        if (n > file.size() - at) fail("it ends early (truncated?)");
        if (n > 0) std::memcpy(to, file.data() + at, n);
        at += n;
    };
    auto value = [&](auto& v) { bytes(&v, sizeof(v)); };
    auto array = [&](auto& a) {
        std::uint64_t n = 0;
        value(n);
        if (n > (file.size() - at) / sizeof(a[0])) fail("an array length of " + std::to_string(n));
        a.resize(n);
        bytes(a.data(), n * sizeof(a[0]));
    };
    char head[sizeof(slabMagic)];
    bytes(head, sizeof(head));
    if (std::memcmp(head, slabMagic, sizeof(slabMagic)) != 0) fail("wrong file type");
    std::uint32_t version = 0;
    value(version);
    // The checksum before the version: a damaged version field is no older file
    refuseDamagedVersion(file, slabVersion, firstSealedSlabStateVersion, slabMagic,
                         "slab state file '" + path + "'");
    if (version >= oldestSlabStateVersion && version < slabVersion) {
        throw Error("slab state file '" + path + "' is of version " + std::to_string(version)
                    + ", older than this build reads (" + std::to_string(slabVersion)
                    + "): convert it with '" + convertCommand(path) + "'");
    }
    if (version != slabVersion) {
        fail("version " + std::to_string(version) + ", expected " + std::to_string(slabVersion));
    }
    verifyChecksum(file, slabMagic, "slab state file '" + path + "'");
    std::vector<char> record;
    array(record);
    std::vector<double> key;
    array(key);
    const std::vector<double> here = slabKey(settings_);
    if (key != here) {
        // The key as the disc engine's with the depth in the skin's place, which the
        // comparison leaves out: named on its own, as the walls after it
        const SplitKey fileKey = splitWallsRecord(key);
        const SplitKey hereKey = splitWallsRecord(here);
        const std::vector<double>& a = fileKey.rest;
        const std::vector<double>& b = hereKey.rest;
        std::vector<Difference> differ = compareSettingsKeys(a, b, settings_);
        // A mesh numbered otherwise puts the depth a last digit apart too
        const double extent = std::max(extentOf(settings_.box), b.back());
        if (!a.empty() && a[0] == b[0] && !sameCoordinate(a.back(), b.back(), extent)) {
            const auto [inFile, asked] = textsApart(a.back(), b.back());
            differ.push_back({"slabDepth", inFile + " m", asked + " m"});
        }
        for (const Difference& d : compareWallsRecords(fileKey.walls, hereKey.walls)) {
            differ.push_back(d);
        }
        if (!differ.empty()) {
            throw Error("slab state file '" + path + "' was written with other settings: "
                        + describe(differ));
        }
    }
    SlabSystem t(settings_);
    std::uint8_t hasRecipe = 0;
    value(hasRecipe);
    if (hasRecipe) {
        BedRecipe recipe;
        array(recipe.countPerClass);
        value(recipe.region);
        value(recipe.seed);
        value(recipe.settleTime);
        value(recipe.keTolerance);
        std::vector<double> placed;
        array(placed);
        if (!placedOfRecord(placed, recipe.placed)) {
            fail("a record of placed particles of " + std::to_string(placed.size()) + " values");
        }
        std::vector<double> settleFriction;
        array(settleFriction);
        if (!settleFrictionOfRecord(settleFriction, recipe.settleFriction)) {
            fail("a settle friction of " + std::to_string(settleFriction.size()) + " values");
        }
        if (recipe.countPerClass.size() != static_cast<std::size_t>(nClasses_)) {
            fail("a bed recipe of " + std::to_string(recipe.countPerClass.size()) + " classes");
        }
        t.recipe_ = recipe;
    }
    value(t.stepCount_);
    value(t.listBuilds_);
    double fileSkin = 0.0;
    value(fileSkin);
    value(t.lastBuildStep_);
    if (!(fileSkin > 0.0) || t.lastBuildStep_ < -1 || t.lastBuildStep_ > t.stepCount_) {
        fail("a skin of " + formatValue(fileSkin) + " m built at step "
             + std::to_string(t.lastBuildStep_));
    }
    // An adaptive skin continues from the file's (within its bounds); a fixed one stays,
    // and a list of another skin is built anew.
    if (t.adaptiveSkin_) t.setSkin(std::clamp(fileSkin, t.skinMin_, t.skinMax_));
    const bool sameSkin = fileSkin == t.skin_;
    std::vector<double> wallData;
    array(wallData);
    // The planes (the cylinders are the settings', which the key holds): at least the
    // settings' own, and those added by addWall
    if (wallData.size() % 6 != 0 || wallData.size() < 6 * planeWalls(settings_).size()) {
        fail("a bad wall list");
    }
    t.walls_.clear();
    for (std::size_t k = 0; k < wallData.size(); k += 6) {
        t.walls_.push_back({Eigen::Vector3d(wallData[k], wallData[k + 1], wallData[k + 2]),
                            Eigen::Vector3d(wallData[k + 3], wallData[k + 4], wallData[k + 5])});
    }
    t.p_.forEachArray([&](auto& a) { array(a); });
    const std::size_t n = t.p_.size();
    bool sizesAgree = true;
    t.p_.forEachArray([&](const auto& a) { sizesAgree = sizesAgree && a.size() == n; });
    if (!sizesAgree) fail("particle arrays of different lengths");
    std::uint8_t ready = 0;
    value(ready);
    array(t.pairs_.i); array(t.pairs_.j); array(t.pairs_.law); array(t.pairs_.xi);
    array(t.pairs_.groupStart);
    array(t.wallContacts_.start); array(t.wallContacts_.wall); array(t.wallContacts_.xi);
    std::uint64_t checksum = 0;
    value(checksum);   // verified above
    char tail[sizeof(slabMagic)];
    bytes(tail, sizeof(tail));
    if (std::memcmp(tail, slabMagic, sizeof(slabMagic)) != 0) fail("no end marker");
    const std::size_t np = t.pairs_.i.size();
    const std::size_t nw = t.wallContacts_.wall.size();
    bool listOk = t.pairs_.j.size() == np && t.pairs_.law.size() == np && t.pairs_.xi.size() == np
                  && t.wallContacts_.xi.size() == nw;
    for (std::size_t k = 0; listOk && k < np; ++k) {
        listOk = t.pairs_.i[k] >= 0 && t.pairs_.i[k] < t.pairs_.j[k]
                 && static_cast<std::size_t>(t.pairs_.j[k]) < n && t.pairs_.law[k] >= 0
                 && t.pairs_.law[k] < nClasses_ * nClasses_;
    }
    for (std::size_t k = 0; listOk && k < nw; ++k) {
        listOk = t.wallContacts_.wall[k] >= 0 && t.wallContacts_.wall[k] < t.wallCount();
    }
    listOk = listOk && (ready == 0 || (t.pairs_.groupStart.size() == nPairGroups + 1
                                       && t.wallContacts_.start.size() == n + 1
                                       && t.pairs_.groupStart.back() == static_cast<int>(np)
                                       && t.wallContacts_.start.back() == static_cast<int>(nw)));
    if (!listOk) fail("a bad contact list");
    checkLoadedParticles({n, t.p_.x.data(), t.p_.y.data(), t.p_.z.data(), t.p_.vx.data(),
                          t.p_.vy.data(), t.p_.vz.data(), t.p_.radius.data()},
                         settings_.box, settings_.slabDepth, "slab state file '" + path + "'");
    t.runRecord_.assign(record.begin(), record.end());
    t.listValid_ = ready != 0 && sameSkin;
    t.forcesValid_ = ready != 0;
    *this = std::move(t);
}

bool SlabSystem::loadBed(const std::string& path, const BedRecipe& recipe)
{
    SlabSystem t(settings_);
    t.load(path);
    const std::vector<Difference> differ =
        compareBed(t.recipe(), t.p_.classIndex, recipe, settings_);
    if (!differ.empty()) {
        throw Error("bed '" + path + "' was made for other particles: " + describe(differ));
    }
    const bool checked = t.recipe_.has_value();
    *this = std::move(t);
    return checked;
}

} // namespace dem
