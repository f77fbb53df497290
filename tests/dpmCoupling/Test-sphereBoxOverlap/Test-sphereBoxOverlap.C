/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
-------------------------------------------------------------------------------
Application
    Test-sphereBoxOverlap

Description
    Checks of the sphere-box volume (sphereBoxOverlap.H) against numbers
    from outside its formula: the sphere, a half, a quarter, an octant and
    the spherical cap pi H^2 (3R - H)/3 cut by one and two more planes
    (textbook); a box unbounded in z against the column volume
    (sphereColumnOverlap.H, its own derivation); random boxes cut by one to
    six planes against an adaptive quadrature over z of the exact
    disc-rectangle area (discRectangleOverlap.H); the volumes over cells
    that tile space adding up to 4/3 pi R^3; the same volume for the axes
    permuted; no NaN and no negative volume at tangency, with an edge or a
    corner on the sphere, and for a box of zero width. GoogleTest cases
    (suite SphereBoxOverlap); no case:

        Test-sphereBoxOverlap [--gtest_filter=Suite.Name]

\*---------------------------------------------------------------------------*/

#include "couplingTestMain.H"
#include "sphereBoxOverlap.H"
#include "discRectangleOverlap.H"
#include "columnQuadrature.H"

#include <algorithm>
#include <random>
#include <vector>

using namespace Foam;


//- The box volume by quadrature over z of the disc-rectangle area, to an
//  absolute tolerance tol. The area has square-root kinks where the
//  section's radius passes an edge's or a corner's distance from the
//  axis: the z range is split there, and each panel mapped by the
//  smoothstep z = z0 + (z1 - z0)(3t^2 - 2t^3), whose vanishing slope at
//  both ends makes the integrand smooth for Gauss-Legendre
static scalar quadratureBoxVolume
(
    const scalar xc, const scalar yc, const scalar zc, const scalar R,
    const scalar x0, const scalar x1, const scalar y0, const scalar y1,
    const scalar z0, const scalar z1, const scalar tol
)
{
    static const columnQuadrature::gaussLegendre rule(12);
    const auto area = [&](const double z)
    {
        const double rho2 = R*R - (z - zc)*(z - zc);
        return rho2 > 0
          ? discRectangleOverlap(xc, yc, std::sqrt(rho2), x0, x1, y0, y1)
          : 0.0;
    };
    const double a = max(z0, zc - R), b = min(z1, zc + R);
    if (a >= b) return 0;
    std::vector<double> cuts{a, b};
    const double dx[2] = {x0 - xc, x1 - xc}, dy[2] = {y0 - yc, y1 - yc};
    std::vector<double> distances{dx[0]*dx[0], dx[1]*dx[1], dy[0]*dy[0], dy[1]*dy[1]};
    for (const double u : dx) for (const double v : dy) distances.push_back(u*u + v*v);
    for (const double d2 : distances)
    {
        if (d2 < R*R)
        {
            for (const double z : {zc - std::sqrt(R*R - d2), zc + std::sqrt(R*R - d2)})
            {
                if (a < z && z < b) cuts.push_back(z);
            }
        }
    }
    std::sort(cuts.begin(), cuts.end());
    double V = 0;
    for (size_t k = 0; k + 1 < cuts.size(); ++k)
    {
        const double lo = cuts[k], h = cuts[k + 1] - cuts[k];
        const auto mapped = [&](const double t)
        {
            return area(lo + h*t*t*(3 - 2*t))*6*h*t*(1 - t);
        };
        V += columnQuadrature::adaptive
        (
            rule, mapped, 0, 1, rule.integrate(mapped, 0, 1), tol/cuts.size()
        );
    }
    return V;
}


static const scalar pi = constant::mathematical::pi;
static const scalar R = 1.25e-3;
static const scalar Vs = 4*pi*R*R*R/3;
// Round-off of a few dozen terms of size R^3
static const scalar roundOff = 1e-14*Vs;
static const scalar xc = 0.3e-3, yc = -0.7e-3, zc = 0.4e-3, big = 3*R;

// The random boxes of the tests below: each test draws from its own
// generator, seeded alike
static std::mt19937_64 generator()
{
    return std::mt19937_64(23);
}


// Limits (textbook)
TEST(SphereBoxOverlap, TextbookLimits)
{
    const auto box = [&](scalar x0, scalar x1, scalar y0, scalar y1, scalar z0, scalar z1)
    {
        return sphereBoxOverlap(xc, yc, zc, R, x0, x1, y0, y1, z0, z1);
    };
    const scalar xl = xc - big, xh = xc + big, yl = yc - big, yh = yc + big;
    const scalar zl = zc - big, zh = zc + big;
    checkAbsolute("sphere in a wide box", box(xl, xh, yl, yh, zl, zh), Vs, roundOff);
    checkAbsolute("half-space x > xc", box(xc, xh, yl, yh, zl, zh), Vs/2, roundOff);
    checkAbsolute("half-space z < zc", box(xl, xh, yl, yh, zl, zc), Vs/2, roundOff);
    checkAbsolute("quarter y > yc, z < zc", box(xl, xh, yc, yh, zl, zc), Vs/4, roundOff);
    for (int i = 0; i < 8; ++i)
    {
        const bool X = i & 1, Y = i & 2, Z = i & 4;
        checkAbsolute
        (
            "octant " + std::to_string(i),
            box(X ? xc : xl, X ? xh : xc, Y ? yc : yl, Y ? yh : yc, Z ? zc : zl, Z ? zh : zc),
            Vs/8, roundOff
        );
    }
    for (const scalar h : {0.4*R, -0.3*R, 0.97*R})
    {
        const scalar H = R - h;
        const scalar cap = pi*H*H*(3*R - H)/3;
        const std::string at = " at " + std::to_string(h/R).substr(0, 5) + " R";
        checkAbsolute("cap z > zc + h" + at, box(xl, xh, yl, yh, zc + h, zh), cap, roundOff);
        checkAbsolute("cap x < xc - h" + at, box(xl, xc - h, yl, yh, zl, zh), cap, roundOff);
        checkAbsolute("half a cap z > zc + h, x > xc" + at, box(xc, xh, yl, yh, zc + h, zh), cap/2, roundOff);
        checkAbsolute("a quarter cap y > yc + h, x < xc, z > zc" + at, box(xl, xc, yc + h, yh, zc, zh), cap/4, roundOff);
    }
    // An edge and a corner on the sphere: nothing beyond them
    checkAbsolute("edge on the sphere", box(xc + 0.6*R, xh, yc + 0.8*R, yh, zl, zh), 0, roundOff);
    checkAbsolute("corner on the sphere", box(xc + 0.48*R, xh, yc + 0.6*R, yh, zc + 0.64*R, zh), 0, roundOff);
    checkAbsolute("tangent face", box(xc + R, xh, yl, yh, zl, zh), 0, roundOff);
    checkAbsolute("box of zero width", box(xc, xc, yl, yh, zl, zh), 0, roundOff);
}


// Axes permuted: the same volume
TEST(SphereBoxOverlap, SameVolumeWithTheAxesPermuted)
{
    std::mt19937_64 gen(generator());
    std::uniform_real_distribution<scalar> u(0, 1);
    scalar worst = 0;
    for (int n = 0; n < 200; ++n)
    {
        scalar lo[3], hi[3], c[3] = {xc, yc, zc};
        for (int k = 0; k < 3; ++k)
        {
            lo[k] = c[k] + (2*u(gen) - 1.2)*R;
            hi[k] = lo[k] + 1.5*u(gen)*R;
        }
        const scalar a = sphereBoxOverlap(c[0], c[1], c[2], R, lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
        const scalar b = sphereBoxOverlap(c[1], c[2], c[0], R, lo[1], hi[1], lo[2], hi[2], lo[0], hi[0]);
        const scalar d = sphereBoxOverlap(c[2], c[0], c[1], R, lo[2], hi[2], lo[0], hi[0], lo[1], hi[1]);
        worst = max(worst, max(mag(a - b), mag(a - d)));
    }
    checkAbsolute("200 random boxes with the axes permuted: worst difference", worst, 0, roundOff);
}


// A box unbounded in z is the column (sphereColumnOverlap.H)
TEST(SphereBoxOverlap, BoxUnboundedInZIsTheColumn)
{
    std::mt19937_64 gen(generator());
    std::uniform_real_distribution<scalar> u(0, 1);
    scalar worst = 0;
    for (int n = 0; n < 500; ++n)
    {
        const scalar x0 = xc + (2.4*u(gen) - 1.7)*R, x1 = x0 + 2*u(gen)*R;
        const scalar y0 = yc + (2.4*u(gen) - 1.7)*R, y1 = y0 + 2*u(gen)*R;
        const scalar V = sphereBoxOverlap(xc, yc, zc, R, x0, x1, y0, y1, zc - big, zc + big);
        worst = max(worst, mag(V - sphereColumnOverlap(xc, yc, R, x0, x1, y0, y1)));
    }
    checkAbsolute("500 boxes through the sphere in z vs the column volume: worst error", worst, 0, 10*roundOff);
}


// Random boxes by the number of planes cutting the sphere, against the
// quadrature of the disc-rectangle areas (to 1e-14 Vs)
TEST(SphereBoxOverlap, RandomBoxesAgainstQuadrature)
{
    std::mt19937_64 gen(generator());
    std::uniform_real_distribution<scalar> u(0, 1);
    scalar worst[7] = {0, 0, 0, 0, 0, 0, 0};
    label count[7] = {0, 0, 0, 0, 0, 0, 0};
    label need = 0;
    while (need < 6)
    {
        const scalar r = (u(gen) < 0.5 ? 0.75e-3 : 1.25e-3);
        scalar lo[3], hi[3], c[3];
        label planes = 0;
        for (int k = 0; k < 3; ++k)
        {
            const scalar w = (0.1 + 2.9*u(gen))*r;
            lo[k] = 0.01*(k + 1);
            hi[k] = lo[k] + w;
            c[k] = lo[k] - r + u(gen)*(w + 2*r);
            planes += (mag(lo[k] - c[k]) < r) + (mag(hi[k] - c[k]) < r);
        }
        if (planes == 0 || count[planes] >= 150) continue;
        const scalar V0 = 4*pi*r*r*r/3;
        const scalar V = sphereBoxOverlap(c[0], c[1], c[2], r, lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]);
        const scalar Vq = quadratureBoxVolume(c[0], c[1], c[2], r, lo[0], hi[0], lo[1], hi[1], lo[2], hi[2], 1e-14*V0);
        worst[planes] = max(worst[planes], std::isfinite(V) ? mag(V - Vq)/V0 : GREAT);
        if (++count[planes] == 150) ++need;
    }
    for (label k = 1; k <= 6; ++k)
    {
        checkAbsolute
        (
            "150 boxes cut by " + std::to_string(k) + " of their 6 planes vs quadrature: worst error/(4/3 pi R^3)",
            worst[k], 0, 1e-13
        );
    }
}


// Cells that tile space: one sphere's volumes add up to the sphere
TEST(SphereBoxOverlap, CellsThatTileSpaceAddUpToTheSphere)
{
    std::mt19937_64 gen(generator());
    std::uniform_real_distribution<scalar> u(0, 1);
    scalar worst = 0, negative = 0;
    for (int n = 0; n < 50; ++n)
    {
        const scalar r = (0.3 + 0.7*u(gen))*R;
        const scalar h = (0.5 + 1.5*u(gen))*r;       // cells of 0.5 d to 2 d
        const scalar c[3] = {u(gen)*h, u(gen)*h, u(gen)*h};
        const int m = int(std::ceil(r/h)) + 1;
        scalar sum = 0;
        for (int i = -m; i <= m; ++i)
        for (int j = -m; j <= m; ++j)
        for (int k = -m; k <= m; ++k)
        {
            const scalar V = sphereBoxOverlap
            (
                c[0], c[1], c[2], r, i*h, (i + 1)*h, j*h, (j + 1)*h, k*h, (k + 1)*h
            );
            negative = min(negative, V);
            sum += V;
        }
        worst = max(worst, mag(sum - 4*pi*r*r*r/3)/(4*pi*r*r*r/3));
    }
    checkAbsolute("50 spheres over cells of 0.5-2 diameters: worst |sum - 4/3 pi R^3|/(4/3 pi R^3)", worst, 0, 1e-13);
    checkAbsolute("the smallest cell volume of those", negative, 0, 0);
}


int main(int argc, char *argv[])
{
    return couplingTest::main(argc, argv, couplingTest::noCase);
}


// ************************************************************************* //
