// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared set-up of the verification suite: the reference tables beside the repository, one
// size class in either engine through the facade, and a particle placed and read as 3-vectors
// in both engines (the 2D engine's discs move in the x-y plane and spin about z).

#include "TestHelpers.hpp"
#include "dem/Facade.hpp"

#include <Eigen/Core>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace dem::verification {

constexpr double pi = 3.14159265358979323846;
using Vec3 = Eigen::Vector3d;

/// Rows of a comma-separated table: '#' lines are comments, the first other line names the
/// columns.
struct Table {
    std::vector<std::map<std::string, std::string>> rows;

    /// The rows whose column `key` reads `value`.
    std::vector<std::map<std::string, std::string>> where(const std::string& key,
                                                          const std::string& value) const
    {
        std::vector<std::map<std::string, std::string>> out;
        for (const auto& r : rows) {
            if (r.at(key) == value) out.push_back(r);
        }
        return out;
    }
};

inline double number(const std::map<std::string, std::string>& row, const std::string& column)
{
    return std::stod(row.at(column));
}

/// The folder of the reference curves (see CMakeLists.txt and its SOURCES.md).
inline std::string referenceFolder() { return DEM_VERIFICATION_REFERENCE; }

/// The table `file` of the reference folder; none if the file cannot be read.
inline std::optional<Table> readReference(const std::string& file)
{
    std::ifstream in(referenceFolder() + "/" + file);
    if (!in) return std::nullopt;
    Table t;
    std::vector<std::string> header;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> cells;
        std::stringstream s(line);
        std::string cell;
        while (std::getline(s, cell, ',')) cells.push_back(cell);
        if (line.back() == ',') cells.emplace_back();
        if (header.empty()) {
            header = cells;
            continue;
        }
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < header.size(); ++k) row[header[k]] = k < cells.size() ? cells[k] : "";
        t.rows.push_back(std::move(row));
    }
    return t;
}

/// Whether the reference tables must be present: the environment variable
/// DPMFOAM2D_REQUIRE_REFERENCE set to anything but "" or "0" (CI, where the folder is beside
/// the repository), so that a missing table fails its test instead of skipping it.
inline bool referenceRequired()
{
    const char* v = std::getenv("DPMFOAM2D_REQUIRE_REFERENCE");
    return v && *v && std::string(v) != "0";
}

/// Reads reference table `file` into `table`, or skips the test naming the missing file
/// (fails it if referenceRequired()).
#define DEM_REFERENCE_OR_SKIP(table, file)                                                      \
    const std::optional<::dem::verification::Table> table##Read =                               \
        ::dem::verification::readReference(file);                                               \
    if (!table##Read) {                                                                         \
        if (::dem::verification::referenceRequired()) {                                         \
            GTEST_FAIL() << "reference table " << ::dem::verification::referenceFolder() << "/" \
                         << (file) << " is absent, and DPMFOAM2D_REQUIRE_REFERENCE says it "    \
                            "must be present (the folder of SOURCES.md beside the repository)"; \
        }                                                                                       \
        GTEST_SKIP() << "reference table " << ::dem::verification::referenceFolder() << "/"     \
                     << (file) << " is absent (the folder of SOURCES.md beside the repository)"; \
    }                                                                                           \
    const ::dem::verification::Table& table = *table##Read

/// One size class of diameter d and density rho in `box`, no gravity, no friction, in the 2D
/// engine (dimension 2) or the slab (3, depth `depth`).
inline Settings oneClass(double d, double rho, const Box& box, int dimension, double depth,
                         double dt)
{
    Settings s;
    s.classes = {{"sphere", d, rho}};
    s.box = box;
    s.gravity[0] = 0.0;
    s.gravity[1] = 0.0;
    s.dt = dt;
    s.dimension = dimension;
    s.slabDepth = dimension == 3 ? depth : 0.0;
    s.contact.frictionParticle = 0.0;
    s.contact.frictionWall = 0.0;
    return s;
}

inline double sphereMass(double d, double rho) { return rho * pi * d * d * d / 6.0; }

/// Duration of a head-on contact of the linear spring-dashpot, its normal force clamped at
/// zero, at restitution e (TestHelpers.hpp, from the damped oscillator, not the library), s.
inline double contactTime(double mEff, double kn, double e)
{
    return ::dem::test::contactTime(mEff, kn, e);
}

/// Hertz's elastic contact time of a head-on impact at normal speed v (Johnson 1985, Contact
/// Mechanics, section 11.4, written here from it): 2.94320 delta_max/v with
/// delta_max = (15 mEff v^2/(16 E* sqrt(R*)))^2/5, s.
inline double hertzPeakOverlap(double mEff, double rEff, double eStar, double v)
{
    return std::pow(15.0 * mEff * v * v / (16.0 * eStar * std::sqrt(rEff)), 0.4);
}
inline double hertzImpactDuration(double mEff, double rEff, double eStar, double v)
{
    return 2.94320 * hertzPeakOverlap(mEff, rEff, eStar, v) / v;
}

/// The HertzMindlin law in `s`: every class of Young's modulus `youngs` and Poisson's ratio
/// `poisson`, on rigid walls (a Young's modulus 1e20 times the particles').
inline void setHertzMindlin(Settings& s, double youngs, double poisson)
{
    s.contact.law = ContactLawType::hertzMindlin;
    for (ParticleClass& c : s.classes) {
        c.youngsModulus = youngs;
        c.poissonRatio = poisson;
    }
    s.contact.wallYoungsModulus = 1e20 * youngs;
    s.contact.wallPoissonRatio = poisson;
    s.contact.kt = -1.0;
}

/// A particle placed and read as 3-vectors through the facade, in either engine.
inline void place(Simulation& sim, int cls, const Vec3& x, const Vec3& v, const Vec3& w)
{
    if (sim.settings().dimension == 3) {
        sim.addParticle(cls, Vector3{x.x(), x.y(), x.z()}, Vector3{v.x(), v.y(), v.z()},
                        Vector3{w.x(), w.y(), w.z()});
    } else {
        sim.addParticle(cls, x.x(), x.y(), v.x(), v.y(), w.z());
    }
}
inline Vec3 position(const Simulation& sim, int i)
{
    const bool slab = sim.settings().dimension == 3;
    return {sim.x()[i], sim.y()[i], slab ? sim.z()[i] : 0.0};
}
inline Vec3 velocity(const Simulation& sim, int i)
{
    const bool slab = sim.settings().dimension == 3;
    return {sim.vx()[i], sim.vy()[i], slab ? sim.vz()[i] : 0.0};
}
inline Vec3 spin(const Simulation& sim, int i)
{
    const bool slab = sim.settings().dimension == 3;
    return {slab ? sim.omegaX()[i] : 0.0, slab ? sim.omegaY()[i] : 0.0, sim.omega()[i]};
}

inline const char* engineName(int dimension) { return dimension == 3 ? "slab" : "2D"; }

/// The suite's error measure of Chung & Ooi's tests as Kratos applies it
/// (DEM_benchmarks Chung_Ooi_class.py): sum |DEM - ref| / sum |ref|.
inline double summedRelativeError(const std::vector<double>& dem, const std::vector<double>& ref)
{
    double num = 0.0, den = 0.0;
    for (std::size_t k = 0; k < ref.size(); ++k) {
        num += std::abs(dem[k] - ref[k]);
        den += std::abs(ref[k]);
    }
    return num / den;
}

} // namespace dem::verification
