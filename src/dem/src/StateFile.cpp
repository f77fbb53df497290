// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Binary state file: everything that the next step reads, so a restarted run continues
// bit for bit (positions, velocities, forces of the last evaluation, the neighbour list
// in its order, the contact history, the reference positions of the skin criterion); the
// caller's record of the run (its models, runRecord()); the recipe of a packed bed (counts,
// region, seed, settling, the placed particles, the settle friction), so that a case can
// check that a bed was made for its particles;
// the step of the last list build (the adaptive skin's clock; the skin itself is the key's
// last entry); and a checksum (64-bit FNV-1a of every byte before it) ahead of the end marker.
// Version policy: the version after the magic names the layout. Each engine writes and
// reads its current version only (2D 9, slab 7; StateConversion.hpp): the loader holds one
// layout, and every state it reads carries its checksum and the run's record. A change of
// the layout raises the version and teaches dpmConvertState (StateConversion.cpp) to read
// the previous one; the converter keeps reading every earlier version (2D 2-8, slab 1-6).
// load() refuses a file of an older version naming its version and the command that
// converts it, and any other version as not a valid state.

#include "StateIntegrity.hpp"
#include "dem/StateConversion.hpp"
#include "dem/StateRecord.hpp"
#include "dem/System.hpp"
#include "dem/WritePoints.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <type_traits>
#include <unistd.h>

namespace dem {

namespace {

const char (&magic)[16] = discStateMagic;
constexpr std::uint32_t version = discStateVersion;

/// Writes through C stdio, so that a failure keeps its OS reason (errno).
class Writer {
public:
    explicit Writer(std::FILE* out) : out_(out) {}
    template <class T> void value(const T& v)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes(&v, sizeof(T));
    }
    template <class T> void array(const std::vector<T>& a)
    {
        value(static_cast<std::uint64_t>(a.size()));
        bytes(a.data(), a.size() * sizeof(T));
    }
    void bytes(const void* data, std::size_t n)
    {
        hash_ = fnv1a64(static_cast<const char*>(data), n, hash_);
        if (error_ == 0 && n > 0 && std::fwrite(data, 1, n, out_) != n) error_ = errno ? errno : EIO;
    }
    /// Hands the buffered bytes to the OS (a kill then leaves them in the file).
    void flush()
    {
        if (error_ == 0 && std::fflush(out_) != 0) error_ = errno ? errno : EIO;
    }
    /// FNV-1a of every byte written so far.
    std::uint64_t hash() const { return hash_; }
    /// The first OS error (0: none).
    int error() const { return error_; }

private:
    std::FILE* out_;
    int error_ = 0;
    std::uint64_t hash_ = fnv1a64(nullptr, 0);
};

std::string reason(int error) { return std::strerror(error); }

class Reader {
public:
    Reader(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}
    template <class T> T value()
    {
        T v;
        read(reinterpret_cast<char*>(&v), sizeof(T));
        return v;
    }
    template <class T> void array(std::vector<T>& a)
    {
        const auto n = value<std::uint64_t>();
        if (n > (bytes_.size() - at_) / sizeof(T)) fail("an array length of " + std::to_string(n));
        a.resize(n);
        read(reinterpret_cast<char*>(a.data()), n * sizeof(T));
    }
    void read(char* to, std::size_t n)
    {
        if (n > bytes_.size() - at_) fail("it ends early (truncated?)");
        if (n > 0) std::memcpy(to, bytes_.data() + at_, n);
        at_ += n;
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

} // namespace

/// Reads and writes System state files.
class StateFile {
public:
    static void save(const System& s, const std::string& path);
    static void load(System& s, const std::string& path);
    static bool loadBed(System& s, const std::string& path, const BedRecipe& recipe);

private:
    static void write(const System& s, Writer& w);
};

void StateFile::write(const System& s, Writer& w)
{
    w.bytes(magic, sizeof(magic));
    w.value(version);
    w.array(std::vector<char>(s.runRecord_.begin(), s.runRecord_.end()));
    // The neighbour skin is last in the key: it only orders the round-off, so a
    // state can be continued with another skin after a fresh list build.
    w.array(settingsKey(s.settings_, s.skin_));
    w.value(static_cast<std::uint8_t>(s.recipe_.has_value()));
    if (s.recipe_) {
        w.array(s.recipe_->countPerClass);
        w.value(s.recipe_->region);
        w.value(s.recipe_->seed);
        w.value(s.recipe_->settleTime);
        w.value(s.recipe_->keTolerance);
        w.array(placedRecord(*s.recipe_));
        w.array(settleFrictionRecord(*s.recipe_));
    }
    w.value(s.stepCount_);
    w.value(s.listBuilds_);
    w.value(s.lastBuildStep_);
    w.value(static_cast<std::uint8_t>(s.listValid_));
    w.value(static_cast<std::uint8_t>(s.forcesValid_));
    w.value(static_cast<std::uint64_t>(s.contactCount_));
    w.value(s.maxOverlap_);
    s.p_.forEachArray([&](const auto& a) { w.array(a); });
    w.flush();
    atWritePoint("stateWrite.part");
    const PairList& pl = s.pairs_;
    w.array(pl.i); w.array(pl.j); w.array(pl.law); w.array(pl.xi);
    w.array(pl.groupStart);
    w.array(s.wallContacts_.start); w.array(s.wallContacts_.wall); w.array(s.wallContacts_.xi);
    const std::uint64_t checksum = w.hash();
    w.value(checksum);
    w.bytes(magic, sizeof(magic));   // end marker
}

void StateFile::save(const System& s, const std::string& path)
{
    namespace fs = std::filesystem;
    auto fail = [&](const std::string& why) {
        throw Error("cannot write state file '" + path + "': " + why);
    };
    const fs::path parent = fs::path(path).parent_path();
    std::error_code ec;
    if (!parent.empty() && !fs::is_directory(parent, ec)) {
        fs::create_directories(parent, ec);
        if (ec) fail("cannot create directory '" + parent.string() + "': " + ec.message());
    }
    // Written beside it, then renamed: a failed write leaves an earlier state whole.
    const std::string tmp = path + ".tmp";
    std::FILE* out = std::fopen(tmp.c_str(), "wb");
    if (!out) fail("cannot create '" + tmp + "': " + reason(errno));
    Writer w(out);
    write(s, w);
    int error = w.error();
    if (std::fflush(out) != 0 && error == 0) error = errno;
    if (std::fclose(out) != 0 && error == 0) error = errno;
    if (error != 0) {
        std::remove(tmp.c_str());
        fail(reason(error) + " (an earlier file there is left as it was)");
    }
    atWritePoint("stateWrite.rename");
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int renameError = errno;
        std::remove(tmp.c_str());
        fail("cannot rename '" + tmp + "' to it: " + reason(renameError));
    }
}

void StateFile::load(System& s, const std::string& path)
{
    const std::string bytes = readStateBytes(path, "state file");
    refuseForeignEngine(bytes, 2, path);
    Reader r(bytes, path);
    char head[sizeof(magic)];
    if (bytes.size() < sizeof(head)) r.fail("wrong file type");
    r.read(head, sizeof(head));
    if (std::memcmp(head, magic, sizeof(magic)) != 0) r.fail("wrong file type");
    const auto fileVersion = r.value<std::uint32_t>();
    // The checksum before the version: a damaged version field is no older file
    refuseDamagedVersion(bytes, version, firstSealedDiscStateVersion, magic, "state file '" + path + "'");
    if (fileVersion >= oldestDiscStateVersion && fileVersion < version) {
        throw Error("state file '" + path + "' is of version " + std::to_string(fileVersion)
                    + ", older than this build reads (" + std::to_string(version)
                    + "): convert it with '" + convertCommand(path) + "'");
    }
    if (fileVersion != version) {
        r.fail("version " + std::to_string(fileVersion) + ", expected " + std::to_string(version));
    }
    verifyChecksum(bytes, magic, "state file '" + path + "'");
    std::vector<char> record;
    r.array(record);
    std::vector<double> key;
    r.array(key);
    const std::vector<double> here = settingsKey(s.settings_, s.skin_);
    const std::vector<Difference> differ = compareSettingsKeys(key, here, s.settings_);
    if (!differ.empty()) {
        throw Error("state file '" + path + "' was written with other settings: "
                    + describe(differ));
    }
    // Read into a copy so that a bad file leaves the running system untouched.
    System t = s;
    // An adaptive skin continues from the file's (within its bounds); a fixed one stays.
    if (t.adaptiveSkin_) t.setSkin(std::clamp(key.back(), t.skinMin_, t.skinMax_));
    const bool sameSkin = key.back() == t.skin_;
    t.recipe_.reset();
    if (r.value<std::uint8_t>() != 0) {
        BedRecipe recipe;
        r.array(recipe.countPerClass);
        recipe.region = r.value<Box>();
        recipe.seed = r.value<std::uint64_t>();
        recipe.settleTime = r.value<double>();
        recipe.keTolerance = r.value<double>();
        std::vector<double> placed;
        r.array(placed);
        if (!placedOfRecord(placed, recipe.placed)) {
            r.fail("a record of placed particles of " + std::to_string(placed.size()) + " values");
        }
        std::vector<double> settleFriction;
        r.array(settleFriction);
        if (!settleFrictionOfRecord(settleFriction, recipe.settleFriction)) {
            r.fail("a settle friction of " + std::to_string(settleFriction.size()) + " values");
        }
        if (recipe.countPerClass.size() != static_cast<std::size_t>(t.nClasses_)) {
            r.fail("a bed recipe of " + std::to_string(recipe.countPerClass.size())
                   + " classes");
        }
        t.recipe_ = recipe;
    }
    t.stepCount_ = r.value<std::int64_t>();
    t.listBuilds_ = r.value<std::int64_t>();
    t.lastBuildStep_ = r.value<std::int64_t>();
    t.listValid_ = r.value<std::uint8_t>() != 0;
    t.forcesValid_ = r.value<std::uint8_t>() != 0;
    t.contactCount_ = static_cast<std::size_t>(r.value<std::uint64_t>());
    t.maxOverlap_ = r.value<double>();
    t.p_.forEachArray([&](auto& a) { r.array(a); });
    PairList& pl = t.pairs_;
    r.array(pl.i); r.array(pl.j); r.array(pl.law); r.array(pl.xi);
    r.array(pl.groupStart);
    if (pl.groupStart.size() != static_cast<std::size_t>(nPairGroups) + 1) {
        // Written with another grouping (a state saved by a run with another number of pair groups):
        // the history is kept, the list is built anew.
        pl.groupStart.clear();
        t.listValid_ = false;
    }
    r.array(t.wallContacts_.start); r.array(t.wallContacts_.wall); r.array(t.wallContacts_.xi);
    r.value<std::uint64_t>();   // the checksum, verified above
    char tail[sizeof(magic)];
    r.read(tail, sizeof(tail));
    if (std::memcmp(tail, magic, sizeof(magic)) != 0) r.fail("no end marker");

    // Consistency of the sizes, so that a damaged file cannot index out of range.
    const std::size_t n = t.p_.size();
    bool ok = true;
    t.p_.forEachArray([&](const auto& a) { ok = ok && a.size() == n; });
    const std::size_t np = pl.i.size();
    ok = ok && pl.j.size() == np && pl.law.size() == np && pl.xi.size() == np
         && t.wallContacts_.wall.size() == t.wallContacts_.xi.size();
    for (std::size_t k = 0; ok && k < np; ++k) {
        ok = pl.i[k] >= 0 && pl.j[k] >= 0 && static_cast<std::size_t>(pl.i[k]) < n
             && static_cast<std::size_t>(pl.j[k]) < n && pl.law[k] >= 0
             && pl.law[k] < t.nClasses_ * t.nClasses_;
    }
    for (std::size_t i = 0; ok && i < n; ++i) {
        ok = t.p_.classIndex[i] >= 0 && t.p_.classIndex[i] < t.nClasses_;
    }
    auto monotone = [](const std::vector<int>& start, std::size_t last) {
        for (std::size_t q = 0; q + 1 < start.size(); ++q) {
            if (start[q] < 0 || start[q] > start[q + 1]) return false;
        }
        return start.empty() || static_cast<std::size_t>(start.back()) == last;
    };
    const WallList& wl = t.wallContacts_;
    // Groups: none before the first list build, else nPairGroups + 1 starts within the list.
    const std::vector<int>& bs = pl.groupStart;
    if (!bs.empty()) {
        ok = ok && bs.size() == static_cast<std::size_t>(nPairGroups) + 1 && bs.front() >= 0
             && monotone(bs, static_cast<std::size_t>(bs.back()))
             && static_cast<std::size_t>(bs.back()) <= np;
    }
    ok = ok && t.lastBuildStep_ >= -1 && t.lastBuildStep_ <= t.stepCount_
         && (!t.listValid_ || !bs.empty())
         && monotone(wl.start, wl.wall.size())
         && (!t.listValid_ || wl.start.size() == n + 1);
    for (std::size_t s2 = 0; ok && s2 < wl.wall.size(); ++s2) {
        ok = wl.wall[s2] >= 0 && static_cast<std::size_t>(wl.wall[s2]) < t.walls_.size();
    }
    if (!ok) r.fail("inconsistent array sizes or indices");
    checkLoadedParticles({n, t.p_.x.data(), t.p_.y.data(), nullptr, t.p_.vx.data(), t.p_.vy.data(),
                          nullptr, t.p_.radius.data()},
                         t.settings_.box, 0.0, "state file '" + path + "'");
    t.runRecord_.assign(record.begin(), record.end());
    if (!sameSkin) t.listValid_ = false;   // candidates of the old skin: build anew
    s = std::move(t);
}

bool StateFile::loadBed(System& s, const std::string& path, const BedRecipe& recipe)
{
    System t = s;
    load(t, path);
    const std::vector<Difference> differ =
        compareBed(t.recipe(), t.p_.classIndex, recipe, s.settings_);
    if (!differ.empty()) {
        throw Error("bed '" + path + "' was made for other particles: " + describe(differ));
    }
    const bool checked = t.recipe_.has_value();
    s = std::move(t);
    return checked;
}

void checkStatePath(const std::string& path)
{
    namespace fs = std::filesystem;
    auto fail = [&](const std::string& why) {
        throw Error("cannot write state file '" + path + "': " + why);
    };
    if (path.empty()) throw Error("no state file name given");
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        fail("it is a directory; name a file (e.g. '" + (fs::path(path) / "packedBed.state").string()
             + "')");
    }
    // The nearest existing directory on the way (save() creates the rest).
    fs::path dir = fs::path(path).parent_path();
    if (dir.empty()) dir = ".";
    while (!fs::exists(dir, ec) && dir.has_parent_path() && dir.parent_path() != dir) {
        dir = dir.parent_path();
    }
    if (!fs::is_directory(dir, ec)) fail("'" + dir.string() + "' is not a directory");
    std::string probe = (dir / ".dem.state.probeXXXXXX").string();
    const int fd = mkstemp(probe.data());
    if (fd < 0) fail("cannot create a file in '" + dir.string() + "': " + reason(errno));
    close(fd);
    std::remove(probe.c_str());
}

void System::save(const std::string& path) const { StateFile::save(*this, path); }
void System::load(const std::string& path) { StateFile::load(*this, path); }
bool System::loadBed(const std::string& path, const BedRecipe& recipe)
{
    return StateFile::loadBed(*this, path, recipe);
}

} // namespace dem
