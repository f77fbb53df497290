// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The settings key and bed recipe of state files, and the comparisons that say which entry
// differs (a refused file names the class, the setting, its value and the one asked for).

#include "dem/StateRecord.hpp"
#include "dem/EngineBase.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <utility>

namespace dem {

namespace {

/// Names of the settings key's entries, in its order, before the own coefficients and the skin.
std::vector<std::string> settingsKeyNames(const Settings& s)
{
    std::vector<std::string> names{"number of size classes"};
    for (const auto& c : s.classes) {
        const bool single = c.distribution.type == DiameterDistributionType::single;
        names.push_back("class '" + c.name + (single ? "' diameter" : "' mean diameter"));
        names.push_back("class '" + c.name + "' density");
    }
    for (const char* n : {"contact kn", "contact kt", "contact restitution",
                          "contact restitutionWall", "contact frictionParticle",
                          "contact frictionWall", "box xMin", "box xMax", "box yMin", "box yMax",
                          "gravity x", "gravity y", "DEM step dt", "contact law",
                          "contact tangentialDampingRatio", "contact rollingFriction",
                          "contact rollingFrictionWall", "contact wallYoungsModulus",
                          "contact wallPoissonRatio"}) {
        names.emplace_back(n);
    }
    for (const auto& c : s.classes) {
        names.push_back("class '" + c.name + "' youngsModulus");
        names.push_back("class '" + c.name + "' poissonRatio");
    }
    return names;
}

/// One entry of the own coefficients: a pair's or a class-wall contact's coefficient, the
/// global entry it replaces, and its value.
struct OwnEntry {
    std::string name;     ///< e.g. "contact pair 'small-large' restitution"
    std::string global;   ///< e.g. "contact restitution"
    double value;
};

/// Every kind of contact's coefficients, in the key's order: the pairs of classes a <= b,
/// then each class on the walls; restitution, friction, rolling friction each.
std::vector<OwnEntry> ownEntries(const Settings& s)
{
    std::vector<OwnEntry> out;
    const int n = static_cast<int>(s.classes.size());
    for (int a = 0; a < n; ++a) {
        for (int b = a; b < n; ++b) {
            const ContactCoefficients own = pairCoefficients(s.contact, a, b);
            const std::string name = pairName(s, a, b);
            out.push_back({name + " restitution", "contact restitution", own.restitution});
            out.push_back({name + " frictionParticle", "contact frictionParticle", own.friction});
            out.push_back({name + " rollingFriction", "contact rollingFriction", own.rollingFriction});
        }
    }
    for (int a = 0; a < n; ++a) {
        const ContactCoefficients own = wallCoefficients(s.contact, a);
        const std::string name = wallName(s, a);
        out.push_back({name + " restitutionWall", "contact restitutionWall", own.restitution});
        out.push_back({name + " frictionWall", "contact frictionWall", own.friction});
        out.push_back({name + " rollingFrictionWall", "contact rollingFrictionWall",
                       own.rollingFriction});
    }
    return out;
}

/// The entries of each class's diameter distribution in the key, after the own coefficients
/// where any class has one: its type (0 single, 1 normal, 2 samples), the normal's mean,
/// standard deviation, min and max, the samples' count and their checksum (0 for a single
/// diameter).
constexpr std::size_t distributionEntries = 7;

bool anyDistribution(const Settings& s)
{
    return std::any_of(s.classes.begin(), s.classes.end(), [](const ParticleClass& c) {
        return c.distribution.type != DiameterDistributionType::single;
    });
}

/// The samples' FNV-1a checksum, its top 53 bits (a double holds them exactly).
double samplesChecksum(const std::vector<double>& samples)
{
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (double v : samples) {
        unsigned char bytes[sizeof(double)];
        std::memcpy(bytes, &v, sizeof(double));
        for (unsigned char b : bytes) h = (h ^ b) * 0x100000001b3ull;
    }
    return static_cast<double>(h >> 11);
}

void appendDistribution(std::vector<double>& key, const DiameterDistribution& d)
{
    const bool normal = d.type == DiameterDistributionType::truncatedNormal;
    const bool samples = d.type == DiameterDistributionType::samples;
    key.push_back(normal ? 1.0 : samples ? 2.0 : 0.0);
    for (double v : {d.mean, d.standardDeviation, d.min, d.max}) key.push_back(normal ? v : 0.0);
    key.push_back(samples ? static_cast<double>(d.samples.size()) : 0.0);
    key.push_back(samples ? samplesChecksum(d.samples) : 0.0);
}

std::string distributionCodeName(double code)
{
    if (code == 1.0) return distributionName(DiameterDistributionType::truncatedNormal);
    if (code == 2.0) return distributionName(DiameterDistributionType::samples);
    return "none (one diameter)";
}

/// The law as the key stores it (0 linear, 1 HertzMindlin) and its name.
double lawCode(ContactLawType law) { return law == ContactLawType::hertzMindlin ? 1.0 : 0.0; }

std::string lawName(double code)
{
    if (code == 0.0) return contactLawName(ContactLawType::linear);
    if (code == 1.0) return contactLawName(ContactLawType::hertzMindlin);
    return "unknown law " + formatValue(code);
}

std::string className(const Settings& s, std::size_t k)
{
    return k < s.classes.size() ? "'" + s.classes[k].name + "'" : std::to_string(k);
}

std::string text(double value, int digits)
{
    std::ostringstream s;
    s.precision(digits);
    s << value;
    return s.str();
}

Difference differ(const std::string& name, double inFile, double here, const std::string& unit = "")
{
    const auto [a, b] = textsApart(inFile, here);
    return {name, a + unit, b + unit};
}

/// Box coordinates the same to round-off: a mesh of other cell counts puts its bounds a last
/// digit apart (blockMesh sums its cells), which is no other bed. 1e-12 of the box's extent.
bool sameCoordinate(double a, double b, double extent)
{
    return a == b || std::abs(a - b) <= 1e-12 * extent;
}

double extentOf(const Box& b)
{
    return std::max(std::abs(b.xMax - b.xMin), std::abs(b.yMax - b.yMin));
}

bool sameBox(const Box& a, const Box& b)
{
    const double extent = extentOf(b);
    return sameCoordinate(a.xMin, b.xMin, extent) && sameCoordinate(a.xMax, b.xMax, extent)
           && sameCoordinate(a.yMin, b.yMin, extent) && sameCoordinate(a.yMax, b.yMax, extent);
}

std::pair<std::string, std::string> apart(const Box& a, const Box& b)
{
    const auto [x0a, x0b] = textsApart(a.xMin, b.xMin);
    const auto [x1a, x1b] = textsApart(a.xMax, b.xMax);
    const auto [y0a, y0b] = textsApart(a.yMin, b.yMin);
    const auto [y1a, y1b] = textsApart(a.yMax, b.yMax);
    return {"[" + x0a + ", " + x1a + "] x [" + y0a + ", " + y1a + "] m",
            "[" + x0b + ", " + x1b + "] x [" + y0b + ", " + y1b + "] m"};
}

std::string placedText(const Settings& s, const PlacedParticle& p)
{
    const bool known = p.classIndex >= 0 && p.classIndex < static_cast<int>(s.classes.size());
    const std::string cls = known ? "'" + s.classes[p.classIndex].name + "'"
                                  : std::to_string(p.classIndex);
    if (p.random) return cls + " at random";
    return cls + " at (" + formatValue(p.position.x) + ", " + formatValue(p.position.y)
           + (s.dimension == 3 ? ", " + formatValue(p.position.z) : std::string()) + ") m";
}

bool samePlaced(const PlacedParticle& a, const PlacedParticle& b, int dimension)
{
    if (a.classIndex != b.classIndex || a.random != b.random) return false;
    if (a.random) return true;
    return a.position.x == b.position.x && a.position.y == b.position.y
           && (dimension != 3 || a.position.z == b.position.z);
}

} // namespace

std::pair<std::string, std::string> textsApart(double a, double b)
{
    int digits = 6;
    while (a != b && digits < 17 && text(a, digits) == text(b, digits)) ++digits;
    return {text(a, digits), text(b, digits)};
}

std::vector<double> settingsKey(const Settings& s, double skin)
{
    std::vector<double> key;
    key.push_back(static_cast<double>(s.classes.size()));
    for (const auto& c : s.classes) {
        key.push_back(meanDiameter(c));
        key.push_back(c.density);
    }
    const ContactSettings& c = s.contact;
    for (double v : {c.kn, c.kt, c.restitution, c.restitutionWall, c.frictionParticle,
                     c.frictionWall, s.box.xMin, s.box.xMax, s.box.yMin, s.box.yMax,
                     s.gravity[0], s.gravity[1], s.dt, lawCode(c.law), c.tangentialDampingRatio,
                     c.rollingFriction, c.rollingFrictionWall, c.wallYoungsModulus,
                     c.wallPoissonRatio}) {
        key.push_back(v);
    }
    for (const auto& m : s.classes) {
        key.push_back(m.youngsModulus);
        key.push_back(m.poissonRatio);
    }
    // Every contact's own coefficients where one differs from its global entry: without them
    // the key (and the file) is the one of the global coefficients alone
    const std::vector<std::string> names = settingsKeyNames(s);
    const std::vector<OwnEntry> own = ownEntries(s);
    const bool anyOwn = std::any_of(own.begin(), own.end(), [&](const OwnEntry& e) {
        const auto global = std::find(names.begin(), names.end(), e.global) - names.begin();
        return e.value != key[static_cast<std::size_t>(global)];
    });
    if (anyOwn) {
        for (const OwnEntry& e : own) key.push_back(e.value);
    }
    // Every class's diameter distribution where one has one: without them the key (and the
    // file) is the one of classes of one diameter each
    if (anyDistribution(s)) {
        for (const auto& m : s.classes) appendDistribution(key, m.distribution);
    }
    key.push_back(skin);
    return key;
}

std::vector<Difference> compareSettingsKeys(const std::vector<double>& inFile,
                                            const std::vector<double>& here, const Settings& s)
{
    const std::vector<std::string> names = settingsKeyNames(s);
    const std::vector<OwnEntry> own = ownEntries(s);
    const std::size_t base = names.size();
    const std::size_t distributions = distributionEntries * s.classes.size();
    // A key holds the own coefficients or not, the distributions or not, and the skin last
    // (the four sizes differ for every number of classes)
    auto holdsOwn = [&](const std::vector<double>& key) {
        return key.size() == base + own.size() + 1 || key.size() == base + own.size() + distributions + 1;
    };
    auto holdsDistributions = [&](const std::vector<double>& key) {
        return key.size() == base + distributions + 1
               || key.size() == base + own.size() + distributions + 1;
    };
    auto valid = [&](const std::vector<double>& key) {
        return key.size() == base + 1 || holdsOwn(key) || holdsDistributions(key);
    };
    if (inFile.empty() || here.empty() || inFile[0] != here[0] || !valid(inFile) || !valid(here)) {
        // Another number of classes (or a damaged key): the positions do not correspond.
        const std::string n = inFile.empty() ? std::string("none")
                                             : std::to_string(static_cast<long>(inFile[0]));
        return {{"number of size classes", n, std::to_string(s.classes.size())}};
    }
    auto at = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    const std::size_t box = at("box xMin");   // box xMin, xMax, yMin, yMax
    const double extent = extentOf({here[box], here[box + 1], here[box + 2], here[box + 3]});
    const std::size_t law = at("contact law");
    // The moduli, from the walls' to the classes' last: the linear law does not read them
    const std::size_t moduli = at("contact wallYoungsModulus");
    const bool bothLinear = inFile[law] == 0.0 && here[law] == 0.0;
    // and HertzMindlin does not read the linear law's kn and kt (kt stays the default)
    const bool bothHertz = inFile[law] == 1.0 && here[law] == 1.0;
    std::vector<Difference> d;
    for (std::size_t k = 0; k < base; ++k) {
        if (inFile[k] == here[k]) continue;
        if (k >= box && k < box + 4 && sameCoordinate(inFile[k], here[k], extent)) continue;
        if (bothLinear && k >= moduli) continue;
        if (bothHertz && (names[k] == "contact kn" || names[k] == "contact kt")) continue;
        if (k == law) {
            d.push_back({names[k], lawName(inFile[k]), lawName(here[k])});
            continue;
        }
        Difference e = differ(names[k], inFile[k], here[k]);
        if (names[k] == "contact kt") {   // kt < 0 stands for the default 2/7 kn
            if (inFile[k] < 0) e.inFile += " (2/7 kn)";
            if (here[k] < 0) e.here += " (2/7 kn)";
        }
        d.push_back(e);
    }
    // Each contact's coefficient: its own where the key holds them, else the global entry's.
    // A difference of contacts that both take the global entry is that entry's, named above.
    for (std::size_t q = 0; q < own.size(); ++q) {
        const std::size_t global = at(own[q].global);
        const double a = holdsOwn(inFile) ? inFile[base + q] : inFile[global];
        const double b = holdsOwn(here) ? here[base + q] : here[global];
        if (a == b || (a == inFile[global] && b == here[global])) continue;
        d.push_back(differ(own[q].name, a, b));
    }
    // Each class's distribution: its entries where the key holds them, else one diameter's
    auto distribution = [&](const std::vector<double>& key, std::size_t k) {
        std::vector<double> out(distributionEntries, 0.0);
        if (holdsDistributions(key)) {
            const std::size_t at = key.size() - 1 - distributions + distributionEntries * k;
            std::copy(key.begin() + at, key.begin() + at + distributionEntries, out.begin());
        }
        return out;
    };
    static const char* const entryNames[] = {"distribution", "mean", "standardDeviation",
                                             "min", "max", "samples count", "samples"};
    for (std::size_t k = 0; k < s.classes.size(); ++k) {
        const std::vector<double> a = distribution(inFile, k);
        const std::vector<double> b = distribution(here, k);
        const std::string name = "class '" + s.classes[k].name + "' diameter ";
        if (a[0] != b[0]) {
            d.push_back({name + entryNames[0], distributionCodeName(a[0]), distributionCodeName(b[0])});
            continue;
        }
        for (std::size_t q = 1; q + 1 < distributionEntries; ++q) {
            if (a[q] != b[q]) d.push_back(differ(name + entryNames[q], a[q], b[q]));
        }
        if (a.back() != b.back()) {
            d.push_back({name + entryNames[distributionEntries - 1], "another list", "this one"});
        }
    }
    return d;
}

std::vector<Difference> compareCounts(const std::vector<int>& inFile, const std::vector<int>& here,
                                      const Settings& s)
{
    if (inFile.size() != here.size()) {
        return {{"number of size classes", std::to_string(inFile.size()),
                 std::to_string(here.size())}};
    }
    std::vector<Difference> d;
    for (std::size_t k = 0; k < here.size(); ++k) {
        if (inFile[k] != here[k]) {
            d.push_back({"class " + className(s, k) + " count", std::to_string(inFile[k]),
                         std::to_string(here[k])});
        }
    }
    return d;
}

std::vector<Difference> compareRecipes(const BedRecipe& inFile, const BedRecipe& here,
                                       const Settings& s)
{
    std::vector<Difference> d = compareCounts(inFile.countPerClass, here.countPerClass, s);
    const Box& a = inFile.region;
    const Box& b = here.region;
    if (!sameBox(a, b)) {
        const auto [inA, inB] = apart(a, b);
        d.push_back({"packing region", inA, inB});
    }
    if (inFile.seed != here.seed) {
        d.push_back({"seed", std::to_string(inFile.seed), std::to_string(here.seed)});
    }
    if (inFile.settleTime != here.settleTime) {
        d.push_back(differ("settle time", inFile.settleTime, here.settleTime, " s"));
    }
    if (inFile.keTolerance != here.keTolerance) {
        d.push_back(differ("settling tolerance", inFile.keTolerance, here.keTolerance, " J"));
    }
    if (inFile.placed.size() != here.placed.size()) {
        d.push_back({"placed particles", std::to_string(inFile.placed.size()),
                     std::to_string(here.placed.size())});
    } else {
        for (std::size_t q = 0; q < here.placed.size(); ++q) {
            if (samePlaced(inFile.placed[q], here.placed[q], s.dimension)) continue;
            d.push_back({"placed particle " + std::to_string(q + 1),
                         placedText(s, inFile.placed[q]), placedText(s, here.placed[q])});
        }
    }
    return d;
}

std::vector<double> placedRecord(const BedRecipe& recipe)
{
    std::vector<double> out;
    for (const PlacedParticle& p : recipe.placed) {
        for (double v : {static_cast<double>(p.classIndex), p.random ? 1.0 : 0.0, p.position.x,
                         p.position.y, p.position.z}) {
            out.push_back(v);
        }
    }
    return out;
}

bool placedOfRecord(const std::vector<double>& record, std::vector<PlacedParticle>& placed)
{
    placed.clear();
    if (record.size() % 5 != 0) return false;
    for (std::size_t q = 0; q < record.size(); q += 5) {
        placed.push_back({static_cast<int>(record[q]), record[q + 1] != 0.0,
                          {record[q + 2], record[q + 3], record[q + 4]}});
    }
    return true;
}

void checkPackBed(std::size_t particles, const BedRecipe& recipe)
{
    if (particles != 0) {
        throw Error("packBed: the simulation has " + std::to_string(particles)
                    + " particles already; a bed is packed into an empty one");
    }
    if (!(recipe.settleTime >= 0.0) || !std::isfinite(recipe.settleTime)) {
        throw Error("settle time = " + formatValue(recipe.settleTime) + " s is outside [0, inf)");
    }
    if (!(recipe.keTolerance >= 0.0) || !std::isfinite(recipe.keTolerance)) {
        throw Error("settling tolerance = " + formatValue(recipe.keTolerance)
                    + " J is outside [0, inf)");
    }
}

std::vector<Difference> compareBed(const BedRecipe* inFile, const std::vector<int>& classIndex,
                                   const BedRecipe& here, const Settings& s)
{
    if (inFile) return compareRecipes(*inFile, here, s);
    // No record of how it was made: its counts per class still show a wrong mix.
    std::vector<int> counts(s.classes.size(), 0);
    for (int k : classIndex) ++counts[static_cast<std::size_t>(k)];
    return compareCounts(counts, here.countPerClass, s);
}

std::string describe(const std::vector<Difference>& differences)
{
    std::string text;
    for (const Difference& d : differences) {
        if (!text.empty()) text += "; ";
        text += d.name + " = " + d.inFile + " in the file, " + d.here + " here";
    }
    return text;
}

} // namespace dem

namespace dem {

std::string bedDifferences(const Settings& settings, const BedRecipe& inFile,
                           const BedRecipe& here)
{
    return describe(compareRecipes(inFile, here, settings));
}

} // namespace dem
