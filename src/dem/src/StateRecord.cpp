// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The settings key of state files and the comparison that says which entry differs (a
// refused file names the class, the setting, its value and the one asked for); the bed
// recipe's: BedRecord.cpp.

#include "dem/StateRecord.hpp"
#include "dem/EngineBase.hpp"

#include "RecordCompare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <optional>
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

/// The name of the law of a code in the key (contactLawCode).
std::string lawName(double code)
{
    const std::optional<ContactLawType> law = contactLawOfCode(code);
    return law ? contactLawName(*law) : "unknown law " + formatValue(code);
}

std::string text(double value, int digits)
{
    std::ostringstream s;
    s.precision(digits);
    s << value;
    return s.str();
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
                     s.gravity[0], s.gravity[1], s.dt, contactLawCode(c.law),
                     c.tangentialDampingRatio, c.rollingFriction, c.rollingFrictionWall,
                     c.wallYoungsModulus, c.wallPoissonRatio}) {
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
    // The moduli, from the walls' to the classes' last, and kn, kt: where both keys have one
    // law, the entries it does not read are not compared
    const std::size_t moduli = at("contact wallYoungsModulus");
    const std::optional<ContactLawType> sameLaw =
        inFile[law] == here[law] ? contactLawOfCode(here[law]) : std::nullopt;
    const bool moduliUnread =
        sameLaw && !withLaw(*sameLaw, [](auto policy) { return decltype(policy)::readsModuli; });
    const bool stiffnessUnread =
        sameLaw && !withLaw(*sameLaw, [](auto policy) { return decltype(policy)::readsStiffness; });
    std::vector<Difference> d;
    for (std::size_t k = 0; k < base; ++k) {
        if (inFile[k] == here[k]) continue;
        if (k >= box && k < box + 4 && sameCoordinate(inFile[k], here[k], extent)) continue;
        if (moduliUnread && k >= moduli) continue;
        if (stiffnessUnread && (names[k] == "contact kn" || names[k] == "contact kt")) continue;
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
