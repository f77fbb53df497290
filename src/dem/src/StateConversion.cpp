// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The older layouts of the two engines' state files, read field by field, and the current
// layout written from them in the order of StateFile::write and SlabSystem::save (the tests
// compare a converted file with the current writer's bytes).
//
// 2D (discs): version 2 stored per-pair forces and a per-particle pair index, and its pairs
// were not in groups; 3 added neither; 4 the bed recipe; 5 the step of the last list build;
// 6 the run record and the checksum; 7 the contact law, tangential damping ratio, rolling
// friction and moduli in the settings key. Slab: version 1 had no bed recipe; 2 added it; 3
// the skin and the step of the last list build; 4 the run record and the checksum; 5 the
// key's contact entries as the 2D version 7. 2D version 8 and slab version 6 added the
// recipe's placed particles (an earlier recipe has none); 2D 9 and slab 7 its settle friction
// (an earlier bed settled with the contacts' own).

#include "dem/StateConversion.hpp"

#include "StateIntegrity.hpp"
#include "dem/ContactLaw.hpp"
#include "dem/ContactList.hpp"
#include "dem/Error.hpp"
#include "dem/Facade.hpp"
#include "dem/Particles.hpp"
#include "dem/SlabSystem.hpp"
#include "dem/StateRecord.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <sstream>
#include <vector>

namespace dem {

namespace {

class In {
public:
    In(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}
    template <class T> T value()
    {
        T v;
        raw(&v, sizeof(T));
        return v;
    }
    template <class V> void array(V& a)
    {
        const auto n = value<std::uint64_t>();
        if (n > (bytes_.size() - at_) / sizeof(a[0])) {
            fail("an array length of " + std::to_string(n));
        }
        a.resize(n);
        raw(a.data(), n * sizeof(a[0]));
    }
    void raw(void* to, std::size_t n)
    {
        if (n > bytes_.size() - at_) fail("it ends early (truncated?)");
        if (n > 0) std::memcpy(to, bytes_.data() + at_, n);
        at_ += n;
    }
    void endMarker(const char (&magic)[16])
    {
        char tail[16];
        raw(tail, sizeof(tail));
        if (std::memcmp(tail, magic, sizeof(tail)) != 0) fail("no end marker");
        if (at_ != bytes_.size()) fail("bytes after the end marker");
    }
    [[noreturn]] void fail(const std::string& what) const
    {
        throw Error("state file '" + path_ + "' is not a valid DEM state: " + what);
    }

private:
    const std::string& bytes_;
    std::string path_;
    std::size_t at_ = 0;
};

class Out {
public:
    template <class T> void value(const T& v) { raw(&v, sizeof(T)); }
    template <class V> void array(const V& a)
    {
        value(static_cast<std::uint64_t>(a.size()));
        raw(a.data(), a.size() * sizeof(a[0]));
    }
    void raw(const void* data, std::size_t n) { bytes_.append(static_cast<const char*>(data), n); }
    /// The checksum of everything so far and the end marker.
    void seal(const char (&magic)[16])
    {
        value(fnv1a64(bytes_.data(), bytes_.size()));
        raw(magic, sizeof(magic));
    }
    const std::string& bytes() const { return bytes_; }

private:
    std::string bytes_;
};

/// A recipe of the earlier versions: without a settle friction, and without placed particles
/// unless `placed`.
std::optional<BedRecipe> readRecipe(In& in, bool placed)
{
    if (in.value<std::uint8_t>() == 0) return std::nullopt;
    BedRecipe r;
    in.array(r.countPerClass);
    r.region = in.value<Box>();
    r.seed = in.value<std::uint64_t>();
    r.settleTime = in.value<double>();
    r.keTolerance = in.value<double>();
    if (placed) {
        std::vector<double> record;
        in.array(record);
        if (!placedOfRecord(record, r.placed)) {
            in.fail("a record of placed particles of " + std::to_string(record.size()) + " values");
        }
    }
    return r;
}

void writeRecipe(Out& out, const std::optional<BedRecipe>& r)
{
    out.value(static_cast<std::uint8_t>(r.has_value()));
    if (!r) return;
    out.array(r->countPerClass);
    out.value(r->region);
    out.value(r->seed);
    out.value(r->settleTime);
    out.value(r->keTolerance);
    out.array(placedRecord(*r));
    out.array(settleFrictionRecord(*r));
}

/// The contact law a run record names on its "contactLaw <name>" line (the OpenFOAM side's
/// runs record it), else the linear law.
ContactLawType lawOfRunRecord(const std::vector<char>& record, bool& named)
{
    std::istringstream lines(std::string(record.begin(), record.end()));
    named = false;
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::string entry, name;
        if (words >> entry >> name && entry == "contactLaw") {
            named = true;
            return contactLawFromName(name);
        }
    }
    return ContactLawType::linear;
}

/// The settings key of the earlier versions (the class count, diameter and density per
/// class, kn, kt, the restitutions and frictions, the box, gravity, dt, and the skin or the
/// slab's depth last) with the entries of the current one (StateRecord.cpp's settingsKey)
/// that those did not carry, set as they ran: the law of the run record (else linear), the
/// tangential damping ratio 1, no rolling friction, the moduli unset (0).
std::vector<double> currentKey(In& in, const std::vector<double>& key,
                               const std::vector<char>& record, std::string& notes)
{
    const std::size_t classes = key.empty() ? 0 : static_cast<std::size_t>(key[0]);
    if (classes == 0 || key.size() != 15 + 2 * classes) {
        in.fail("a settings key of " + std::to_string(key.size()) + " values");
    }
    bool named = false;
    ContactLawType law = ContactLawType::linear;
    try {
        law = lawOfRunRecord(record, named);
    } catch (const Error& e) {
        in.fail(std::string("its run record: ") + e.what());
    }
    const ContactSettings defaults;
    std::vector<double> widened(key.begin(), key.end() - 1);
    for (double v : {contactLawCode(law), defaults.tangentialDampingRatio, 0.0, 0.0, 0.0, 0.0}) {
        widened.push_back(v);
    }
    for (std::size_t k = 0; k < 2 * classes; ++k) widened.push_back(0.0);
    widened.push_back(key.back());
    notes += "its settings key carries no contact law, tangential damping ratio, rolling "
             "friction or moduli: written as contactLaw " + contactLawName(law)
             + (named ? " (its run record's)" : " (the default)")
             + ", tangentialDampingRatio " + formatValue(defaults.tangentialDampingRatio)
             + ", rollingFriction and rollingFrictionWall 0, no Young's moduli or Poisson's "
               "ratios; a run with other values refuses it naming them\n";
    return widened;
}

// A pair list's arrays but its groups, and a wall list's, in the writers' order
template <class List> void readPairs(In& in, List& l)
{
    in.array(l.i); in.array(l.j); in.array(l.law); in.array(l.xi);
}
template <class List> void writePairs(Out& out, const List& l)
{
    out.array(l.i); out.array(l.j); out.array(l.law); out.array(l.xi);
}
template <class List> void readWalls(In& in, List& l)
{
    in.array(l.start); in.array(l.wall); in.array(l.xi);
}
template <class List> void writeWalls(Out& out, const List& l)
{
    out.array(l.start); out.array(l.wall); out.array(l.xi);
}

/// A 2D state of versions 2-8 in the current layout.
std::string convertDisc(In& in, std::uint32_t version, std::string& notes)
{
    std::vector<char> record;
    if (version >= 6) in.array(record);
    std::vector<double> key;
    in.array(key);
    if (version < 7) key = currentKey(in, key, record, notes);
    const std::optional<BedRecipe> recipe =
        version >= 4 ? readRecipe(in, version >= 8) : std::nullopt;
    const auto stepCount = in.value<std::int64_t>();
    const auto listBuilds = in.value<std::int64_t>();
    const std::int64_t lastBuildStep = version >= 5 ? in.value<std::int64_t>() : stepCount;
    auto listValid = in.value<std::uint8_t>();
    const auto forcesValid = in.value<std::uint8_t>();
    const auto contacts = in.value<std::uint64_t>();
    const auto maxOverlap = in.value<double>();
    Particles p;
    p.forEachArray([&](auto& a) { in.array(a); });
    PairList pairs;
    readPairs(in, pairs);
    if (version == 2) {
        struct PairForce { double fx, fy, ft; };
        std::vector<PairForce> force;
        std::vector<int> start, entries;
        in.array(force); in.array(start); in.array(entries);
        if (force.size() != pairs.i.size() || entries.size() != 2 * pairs.i.size()) {
            in.fail("inconsistent array sizes or indices");
        }
        listValid = 0;   // pairs in the search's order, not in groups: built anew, history kept
        notes += "its pairs are not in groups: the neighbour list is built anew on the first "
                 "step (the contact history kept)\n";
    } else {
        in.array(pairs.groupStart);
    }
    WallList walls;
    readWalls(in, walls);
    if (version >= 6) in.value<std::uint64_t>();   // the checksum, verified before
    in.endMarker(discStateMagic);

    Out out;
    out.raw(discStateMagic, sizeof(discStateMagic));
    out.value(discStateVersion);
    out.array(record);   // none before version 6
    out.array(key);
    writeRecipe(out, recipe);
    out.value(stepCount);
    out.value(listBuilds);
    out.value(lastBuildStep);
    out.value(listValid);
    out.value(forcesValid);
    out.value(contacts);
    out.value(maxOverlap);
    p.forEachArray([&](const auto& a) { out.array(a); });
    writePairs(out, pairs);
    out.array(pairs.groupStart);
    writeWalls(out, walls);
    out.seal(discStateMagic);
    if (version < 4) {
        notes += "it carries no record of how its bed was packed: a case checks its counts "
                 "per class only\n";
    }
    return out.bytes();
}

/// A slab state of versions 1-6 in the current layout.
std::string convertSlab(In& in, std::uint32_t version, std::string& notes)
{
    std::vector<char> record;
    if (version >= 4) in.array(record);
    std::vector<double> key;
    in.array(key);
    const std::optional<BedRecipe> recipe =
        version >= 2 ? readRecipe(in, version >= 6) : std::nullopt;
    const auto stepCount = in.value<std::int64_t>();
    const auto listBuilds = in.value<std::int64_t>();
    double skin = 0.0;
    std::int64_t lastBuildStep = stepCount;
    if (version >= 3) {
        skin = in.value<double>();
        lastBuildStep = in.value<std::int64_t>();
    } else {
        // The skin of these versions: 0.1 d_min (d_min from the key: the class count, then
        // diameter and density per class), unless the run set Settings::neighbourSkin.
        const std::size_t classes = key.empty() ? 0 : static_cast<std::size_t>(key[0]);
        if (classes == 0 || key.size() < 1 + 2 * classes) {
            in.fail("a settings key of " + std::to_string(key.size()) + " values");
        }
        double dMin = key[1];
        for (std::size_t k = 1; k < classes; ++k) dMin = std::min(dMin, key[1 + 2 * k]);
        skin = 0.1 * dMin;
        notes += "it carries no neighbour skin: written as 0.1 d_min = " + formatValue(skin)
                 + " m, the skin of runs without neighbourSkin (a run with another skin builds "
                   "its neighbour list anew on the first step)\n";
    }
    std::vector<double> wallData;
    in.array(wallData);
    SlabParticles p;
    p.forEachArray([&](auto& a) { in.array(a); });
    const auto ready = in.value<std::uint8_t>();
    SlabPairList pairs;
    readPairs(in, pairs);
    in.array(pairs.groupStart);
    SlabWallList walls;
    readWalls(in, walls);
    if (version >= 4) in.value<std::uint64_t>();   // the checksum, verified before
    in.endMarker(slabStateMagic);
    if (version < 5) key = currentKey(in, key, record, notes);   // after the skin, which reads the old key

    Out out;
    out.raw(slabStateMagic, sizeof(slabStateMagic));
    out.value(slabStateVersion);
    out.array(record);   // none before version 4
    out.array(key);
    writeRecipe(out, recipe);
    out.value(stepCount);
    out.value(listBuilds);
    out.value(skin);
    out.value(lastBuildStep);
    out.array(wallData);
    p.forEachArray([&](const auto& a) { out.array(a); });
    out.value(ready);
    writePairs(out, pairs);
    out.array(pairs.groupStart);
    writeWalls(out, walls);
    out.seal(slabStateMagic);
    if (version < 2) {
        notes += "it carries no record of how its bed was packed: a case checks its counts "
                 "per class only\n";
    }
    return out.bytes();
}

void writeFile(const std::string& bytes, const std::string& path)
{
    auto fail = [&](const std::string& why) {
        throw Error("cannot write state file '" + path + "': " + why);
    };
    const std::string tmp = path + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) fail("cannot create '" + tmp + "': " + std::strerror(errno));
    int error = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() ? 0 : errno;
    if (std::fclose(f) != 0 && error == 0) error = errno;
    if (error != 0) {
        std::remove(tmp.c_str());
        fail(std::strerror(error));
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int renameError = errno;
        std::remove(tmp.c_str());
        fail("cannot rename '" + tmp + "' to it: " + std::strerror(renameError));
    }
}

} // namespace

std::string convertCommand(const std::string& path)
{
    return std::string(stateConverter) + " " + path;
}

StateConversion convertState(const std::string& inPath, const std::string& outPath)
{
    const std::string bytes = readStateBytes(inPath, "state file");
    In in(bytes, inPath);
    char head[16];
    if (bytes.size() < sizeof(head) + sizeof(std::uint32_t)) in.fail("wrong file type");
    in.raw(head, sizeof(head));
    StateConversion c;
    if (std::memcmp(head, discStateMagic, sizeof(head)) == 0) {
        c.dimension = 2;
    } else if (std::memcmp(head, slabStateMagic, sizeof(head)) == 0) {
        c.dimension = 3;
    } else {
        in.fail("wrong file type");
    }
    const bool disc = c.dimension == 2;
    const std::uint32_t current = disc ? discStateVersion : slabStateVersion;
    const std::uint32_t oldest = disc ? oldestDiscStateVersion : oldestSlabStateVersion;
    c.fromVersion = in.value<std::uint32_t>();
    c.toVersion = current;
    if (c.fromVersion < oldest || c.fromVersion > current) {
        in.fail(std::string(disc ? "2D" : "slab") + " state version "
                + std::to_string(c.fromVersion) + ", expected " + std::to_string(oldest)
                + " to " + std::to_string(current));
    }
    if (c.fromVersion == current) {
        verifyChecksum(bytes, disc ? discStateMagic : slabStateMagic,
                       "state file '" + inPath + "'");
        return c;
    }
    const bool sealed = c.fromVersion >= (disc ? firstSealedDiscStateVersion
                                               : firstSealedSlabStateVersion);
    if (sealed) {
        verifyChecksum(bytes, disc ? discStateMagic : slabStateMagic,
                       "state file '" + inPath + "'");
    }
    const std::string converted =
        disc ? convertDisc(in, c.fromVersion, c.notes) : convertSlab(in, c.fromVersion, c.notes);
    if (!sealed) {
        c.notes = "it carries no checksum: its integrity could not be checked (the particles "
                  "are checked when a run loads it)\n"
                  "it carries no record of the run's coupling models\n" + c.notes;
    }
    writeFile(converted, outPath);
    return c;
}

} // namespace dem
