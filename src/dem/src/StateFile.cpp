// Binary state file: everything that the next step reads, so a restarted run continues
// bit for bit (positions, velocities, forces of the last evaluation, the neighbour list
// in its order, the contact history, the reference positions of the skin criterion).
// Version 2 files (before pair blocks) are read too; their list is rebuilt.

#include "dem/System.hpp"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <type_traits>

namespace dem {

namespace {

constexpr char magic[16] = "dpmFoam2D-dem\n";
constexpr std::uint32_t version = 3;
constexpr std::uint32_t version2 = 2;   // stored pair forces and a per-particle index; read, list rebuilt

/// Per-pair record of version-2 files, read and dropped.
struct Version2Force {
    double fx, fy, ft;
};

class Writer {
public:
    explicit Writer(std::ofstream& out) : out_(out) {}
    template <class T> void value(const T& v)
    {
        static_assert(std::is_trivially_copyable_v<T>);
        out_.write(reinterpret_cast<const char*>(&v), sizeof(T));
    }
    template <class T> void array(const std::vector<T>& a)
    {
        value(static_cast<std::uint64_t>(a.size()));
        out_.write(reinterpret_cast<const char*>(a.data()),
                   static_cast<std::streamsize>(a.size() * sizeof(T)));
    }
    void text(const std::string& s)
    {
        value(static_cast<std::uint64_t>(s.size()));
        out_.write(s.data(), static_cast<std::streamsize>(s.size()));
    }

private:
    std::ofstream& out_;
};

class Reader {
public:
    Reader(std::ifstream& in, const std::string& path) : in_(in), path_(path) {}
    template <class T> T value()
    {
        T v;
        read(reinterpret_cast<char*>(&v), sizeof(T));
        return v;
    }
    template <class T> void array(std::vector<T>& a)
    {
        const auto n = value<std::uint64_t>();
        if (n > (std::uint64_t(1) << 34)) fail("an array length of " + std::to_string(n));
        a.resize(n);
        read(reinterpret_cast<char*>(a.data()), n * sizeof(T));
    }
    std::string text()
    {
        const auto n = value<std::uint64_t>();
        if (n > 4096) fail("a name of length " + std::to_string(n));
        std::string s(n, ' ');
        read(s.data(), n);
        return s;
    }
    [[noreturn]] void fail(const std::string& what) const
    {
        throw Error("state file '" + path_ + "' is not a valid DEM state: " + what);
    }

private:
    void read(char* to, std::size_t bytes)
    {
        in_.read(to, static_cast<std::streamsize>(bytes));
        if (!in_) fail("it ends early (truncated?)");
    }
    std::ifstream& in_;
    std::string path_;
};

} // namespace

/// Reads and writes System state files.
class StateFile {
public:
    static void save(const System& s, const std::string& path);
    static void load(System& s, const std::string& path);

private:
    static std::vector<double> settingsKey(const System& s);
};

std::vector<double> StateFile::settingsKey(const System& s)
{
    // Every setting the trajectory depends on (nThreads does not); the
    // neighbour skin last, as it only orders the round-off: a state can be
    // continued with another skin after a fresh neighbour-list build.
    const Settings& st = s.settings_;
    std::vector<double> key;
    key.push_back(static_cast<double>(st.classes.size()));
    for (const auto& c : st.classes) {
        key.push_back(c.diameter);
        key.push_back(c.density);
    }
    const ContactSettings& c = st.contact;
    for (double v : {c.kn, c.kt, c.restitution, c.restitutionWall, c.frictionParticle,
                     c.frictionWall, st.box.xMin, st.box.xMax, st.box.yMin, st.box.yMax,
                     st.gravity[0], st.gravity[1], st.dt, s.skin_}) {
        key.push_back(v);
    }
    return key;
}

void StateFile::save(const System& s, const std::string& path)
{
    const std::string tmp = path + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("cannot write state file '" + tmp + "'");
        Writer w(out);
        out.write(magic, sizeof(magic));
        w.value(version);
        w.array(settingsKey(s));
        w.value(s.stepCount_);
        w.value(s.listBuilds_);
        w.value(static_cast<std::uint8_t>(s.listValid_));
        w.value(static_cast<std::uint8_t>(s.forcesValid_));
        w.value(static_cast<std::uint64_t>(s.contactCount_));
        w.value(s.maxOverlap_);
        s.p_.forEachArray([&](const auto& a) { w.array(a); });
        const PairList& pl = s.pairs_;
        w.array(pl.i); w.array(pl.j); w.array(pl.law); w.array(pl.xiT);
        w.array(pl.groupStart);
        w.array(s.wallContacts_.start); w.array(s.wallContacts_.wall); w.array(s.wallContacts_.xiT);
        out.write(magic, sizeof(magic));   // end marker
        out.flush();
        if (!out) throw Error("cannot write state file '" + tmp + "'");
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        throw Error("cannot rename state file '" + tmp + "' to '" + path + "'");
    }
}

void StateFile::load(System& s, const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open state file '" + path + "'");
    Reader r(in, path);
    char head[sizeof(magic)];
    in.read(head, sizeof(head));
    if (!in || std::memcmp(head, magic, sizeof(magic)) != 0) r.fail("wrong file type");
    const auto fileVersion = r.value<std::uint32_t>();
    if (fileVersion != version && fileVersion != version2) {
        r.fail("version " + std::to_string(fileVersion) + ", expected " + std::to_string(version)
               + " or " + std::to_string(version2));
    }
    std::vector<double> key;
    r.array(key);
    const std::vector<double> here = settingsKey(s);
    if (key.size() != here.size() || !std::equal(here.begin(), here.end() - 1, key.begin())) {
        throw Error("state file '" + path + "' was written with other settings (classes, "
                    "contact, box, gravity or dt differ from this Simulation's)");
    }
    const bool sameSkin = key.back() == here.back();
    // Read into a copy so that a bad file leaves the running system untouched.
    System t = s;
    t.stepCount_ = r.value<std::int64_t>();
    t.listBuilds_ = r.value<std::int64_t>();
    t.listValid_ = r.value<std::uint8_t>() != 0;
    t.forcesValid_ = r.value<std::uint8_t>() != 0;
    t.contactCount_ = static_cast<std::size_t>(r.value<std::uint64_t>());
    t.maxOverlap_ = r.value<double>();
    t.p_.forEachArray([&](auto& a) { r.array(a); });
    PairList& pl = t.pairs_;
    r.array(pl.i); r.array(pl.j); r.array(pl.law); r.array(pl.xiT);
    if (fileVersion == version2) {
        // Pairs in the search's order, not in blocks: a fresh list is built on the first
        // step (the history carries over; the sums' order changes at round-off).
        std::vector<Version2Force> force;
        std::vector<int> start, entries;
        r.array(force); r.array(start); r.array(entries);
        if (force.size() != pl.i.size() || entries.size() != 2 * pl.i.size()) {
            r.fail("inconsistent array sizes or indices");
        }
        pl.groupStart.clear();
        t.listValid_ = false;
    } else {
        r.array(pl.groupStart);
        if (pl.groupStart.size() != static_cast<std::size_t>(nPairGroups) + 1) {
            // Written with another grouping (a state of this session's first blocks):
            // the history is kept, the list is built anew.
            pl.groupStart.clear();
            t.listValid_ = false;
        }
    }
    r.array(t.wallContacts_.start); r.array(t.wallContacts_.wall); r.array(t.wallContacts_.xiT);
    char tail[sizeof(magic)];
    in.read(tail, sizeof(tail));
    if (!in || std::memcmp(tail, magic, sizeof(magic)) != 0) r.fail("no end marker");

    // Consistency of the sizes, so that a damaged file cannot index out of range.
    const std::size_t n = t.p_.size();
    bool ok = true;
    t.p_.forEachArray([&](const auto& a) { ok = ok && a.size() == n; });
    const std::size_t np = pl.i.size();
    ok = ok && pl.j.size() == np && pl.law.size() == np && pl.xiT.size() == np
         && t.wallContacts_.wall.size() == t.wallContacts_.xiT.size();
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
    ok = ok && (!t.listValid_ || !bs.empty())
         && monotone(wl.start, wl.wall.size())
         && (!t.listValid_ || wl.start.size() == n + 1);
    for (std::size_t s2 = 0; ok && s2 < wl.wall.size(); ++s2) {
        ok = wl.wall[s2] >= 0 && static_cast<std::size_t>(wl.wall[s2]) < t.walls_.size();
    }
    if (!ok) r.fail("inconsistent array sizes or indices");
    if (!sameSkin) t.listValid_ = false;   // candidates of the old skin: build anew
    s = std::move(t);
}

void System::save(const std::string& path) const { StateFile::save(*this, path); }
void System::load(const std::string& path) { StateFile::load(*this, path); }

} // namespace dem
