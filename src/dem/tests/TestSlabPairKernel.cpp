// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The slab's batched contact kernel (baseline and AVX2) gives contactForce<3, Law>'s bits for
// every contact of a batch, pairs and walls, under both laws, sticking and sliding, histories
// turned or fresh; and it raises none of the floating-point exceptions the solver traps,
// though it computes both sides of its branches.

#include "StreamingLoops.hpp"
#include "dem/ContactKernel.hpp"
#include "dem/Random.hpp"

#include <gtest/gtest.h>

#include <cfenv>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

using namespace dem;
using Vec3 = Eigen::Vector3d;

namespace {

constexpr int count = 61;   // not a multiple of the packs: the last pack is partly filled

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// A batch of touching pairs (or wall contacts) of plausible magnitudes (spheres of 1.5-2.5
/// mm, overlaps up to 1 % of d, 0.3 m/s, 100 rad/s), one law for all; every fourth history
/// is zero (a fresh contact), others in or out of the tangent plane, some large enough to
/// slide.
struct Contacts {
    std::vector<PairGeometry3> geometry;
    SlabPairBatch batch;

    Contacts(const ContactLaw& law, bool hertz, bool wall, std::uint64_t seed)
    {
        Random rng(seed);
        for (int q = 0; q < count; ++q) {
            const double rI = rng.uniform(0.75e-3, 1.25e-3);
            const double rJ = wall ? 0.0 : rng.uniform(0.75e-3, 1.25e-3);
            const Vec3 dir = Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)).normalized();
            const Vec3 d = (rI + rJ - rng.uniform(0.0, 2e-5)) * dir;
            const Vec3 dv(rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3));
            const Vec3 wI(rng.uniform(-100, 100), rng.uniform(-100, 100), rng.uniform(-100, 100));
            const Vec3 wJ = wall ? Vec3::Zero()
                                 : Vec3(rng.uniform(-100, 100), rng.uniform(-100, 100),
                                        rng.uniform(-100, 100));
            const double size = q % 3 == 0 ? 1e-4 : 1e-6;   // 1e-4 m: slides
            const Vec3 xi = q % 4 == 0 ? Vec3::Zero()
                                       : Vec3(rng.uniform(-size, size), rng.uniform(-size, size),
                                              rng.uniform(-size, size));
            // As the pair loop builds them
            const double dist = std::sqrt(d.x() * d.x() + d.y() * d.y() + d.z() * d.z());
            PairGeometry3 g;
            g.overlap = wall ? rI + rJ - d.norm() : rI + rJ - dist;
            g.nHat = wall ? dir : Vec3(d / dist);
            g.rI = rI;
            g.rJ = rJ;
            g.vRel = wall ? Vec3(dv + (rI * wI).cross(g.nHat))
                          : Vec3(dv + (rI * wI + rJ * wJ).cross(g.nHat));
            g.xiT = xi;
            g.omegaRel = Vec3::Zero();   // not read without rolling resistance
            geometry.push_back(g);
            SlabPairBatch& b = batch;
            b.dx[q] = d.x(); b.dy[q] = d.y(); b.dz[q] = d.z();
            b.rSum[q] = rI + rJ;
            b.nx[q] = g.nHat.x(); b.ny[q] = g.nHat.y(); b.nz[q] = g.nHat.z();
            b.overlap[q] = g.overlap;
            b.dvx[q] = dv.x(); b.dvy[q] = dv.y(); b.dvz[q] = dv.z();
            b.sx[q] = wall ? rI * wI.x() : rI * wI.x() + rJ * wJ.x();
            b.sy[q] = wall ? rI * wI.y() : rI * wI.y() + rJ * wJ.y();
            b.sz[q] = wall ? rI * wI.z() : rI * wI.z() + rJ * wJ.z();
            b.xix[q] = xi.x(); b.xiy[q] = xi.y(); b.xiz[q] = xi.z();
            b.normal[q] = hertz ? law.hertzKn : law.kn;
            b.normalDamping[q] = hertz ? law.hertzEtaN : law.etaN;
            b.tangential[q] = hertz ? law.mindlinKt : law.kt;
            b.tangentialDamping[q] = hertz ? law.mindlinEtaT : law.etaT;
            b.mu[q] = law.mu;
        }
    }
};

ContactLaw linearLaw() { return makeContactLaw(2e-6, 800.0, 800.0 * 2.0 / 7.0, 0.9, 0.3); }
ContactLaw hertzLaw() { return makeHertzMindlinLaw(2e-6, 5e-4, 5e6, 2e6, 0.9, 0.3); }

template <class Law>
void expectContactForceBits(SlabPairLoop kernel, const ContactLaw& law, bool wall,
                            const std::string& what)
{
    constexpr bool hertz = std::is_same_v<Law, HertzMindlin>;
    constexpr double dt = 1e-5;
    Contacts c(law, hertz, wall, 7);
    kernel(c.batch, count, dt);
    int sliding = 0;
    for (int q = 0; q < count; ++q) {
        const PairForce3 f = contactForce<3, Law>(c.geometry[q], law, dt);
        const Vec3 nxF = c.geometry[q].nHat.cross(f.ft);
        const SlabPairBatch& b = c.batch;
        const double got[] = {b.fx[q], b.fy[q], b.fz[q], b.nxFx[q], b.nxFy[q], b.nxFz[q],
                              b.xix[q], b.xiy[q], b.xiz[q], b.overlap[q]};
        const double want[] = {f.force.x(), f.force.y(), f.force.z(), nxF.x(), nxF.y(), nxF.z(),
                               f.xiT.x(), f.xiT.y(), f.xiT.z(), c.geometry[q].overlap};
        for (int k = 0; k < 10; ++k) {
            EXPECT_TRUE(sameBits(got[k], want[k]))
                << what << ": contact " << q << ", output " << k << ": " << got[k]
                << " against contactForce's " << want[k];
        }
        sliding += f.ft.norm() >= 0.999999 * law.mu * (f.force - f.ft).norm() ? 1 : 0;
    }
    EXPECT_GT(sliding, 0) << what << ": the batch has sliding contacts";
    EXPECT_LT(sliding, count) << what << ": the batch has sticking contacts";
}

std::vector<SimdLevel> levels()
{
    std::vector<SimdLevel> l{SimdLevel::baseline};
    if (cpuHasAvx2()) l.push_back(SimdLevel::avx2);
    return l;
}

} // namespace

TEST(SlabPairKernel, GivesContactForceBits)
{
    for (SimdLevel level : levels()) {
        const StreamingLoops& l = streamingLoops(level);
        const std::string name = level == SimdLevel::avx2 ? "avx2" : "baseline";
        expectContactForceBits<LinearSpringDashpot>(l.slabLinearPairs, linearLaw(), false,
                                                    name + " linear pairs");
        expectContactForceBits<HertzMindlin>(l.slabHertzPairs, hertzLaw(), false,
                                             name + " Hertz-Mindlin pairs");
        expectContactForceBits<LinearSpringDashpot>(l.slabLinearWalls, linearLaw(), true,
                                                    name + " linear walls");
        expectContactForceBits<HertzMindlin>(l.slabHertzWalls, hertzLaw(), true,
                                             name + " Hertz-Mindlin walls");
    }
}

TEST(SlabPairKernel, RaisesNoTrappedFloatingPointException)
{
    for (SimdLevel level : levels()) {
        const StreamingLoops& l = streamingLoops(level);
        Contacts linear(linearLaw(), false, false, 11), hertz(hertzLaw(), true, false, 11);
        Contacts linearWall(linearLaw(), false, true, 11), hertzWall(hertzLaw(), true, true, 11);
        std::feclearexcept(FE_ALL_EXCEPT);
        l.slabLinearPairs(linear.batch, count, 1e-5);
        l.slabHertzPairs(hertz.batch, count, 1e-5);
        l.slabLinearWalls(linearWall.batch, count, 1e-5);
        l.slabHertzWalls(hertzWall.batch, count, 1e-5);
        l.slabLinearPairs(linear.batch, count, 0.0);   // an evaluation without history
        EXPECT_EQ(std::fetestexcept(FE_DIVBYZERO | FE_INVALID | FE_OVERFLOW), 0)
            << (level == SimdLevel::avx2 ? "avx2" : "baseline");
    }
}
