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
    dpmUmf

Description
    The minimum fluidization velocities of a case's particles with the
    case's own drag model (constant/particleProperties, dragModel) and gas
    (constant/gasProperties), beside the Wen-Yu Umf that sets the solver's
    inlet velocity U0. Each is a force balance on resting particles in a
    uniform bed of a given voidage (the 3D voidage the drag sees):

    - the mixture's Umf: the drag on all particles (the dictionary's counts
      per class) carries the bed's weight less buoyancy; U0/Umf with it
      says how far above its own Umf the case's bed is fluidized;
    - each class in the mixture: the velocity at which the drag on one of
      its particles carries its weight less buoyancy. A class whose
      velocity is below the mixture's is lifted by the gas at Umf, one
      above it sinks: the ratio of the two classes' velocities is the drag
      model's size contrast, which drives segregation (a polydisperse
      closure such as Beetstra's narrows it);
    - each class alone (a bed of that size only), and the terminal velocity
      of a lone particle.

    The balances are formulation B's (the drag carries each particle's
    weight less buoyancy), which formulation A matches for classes of one
    density. Nothing is written; the mesh is read only because the particles'
    settings are checked against it as for a run. No bed is packed or read.

Usage
    dpmUmf [-voidage '(0.4 0.45 0.5)']

    -voidage <list>  voidages of the bed, one or more, each in (0, 1)
                     (default (0.4 0.45 0.5): the emulsion of the paper's
                     beds is 0.43-0.49 in dpmBedStatistics)

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "gasProperties.H"
#include "dpmCloud.H"
#include "fluidization.H"
#include "finiteNumber.H"

#include <sstream>

namespace
{

//- The voidages of option -voidage, '(e1 e2 ...)' (a single number without
//  parentheses too), each a finite number in (0, 1); a FatalError naming
//  the option and what is wrong otherwise. Read here rather than by
//  OpenFOAM's list reader, whose messages name neither the option nor the
//  value (and 1e400 becomes inf, which traps at the first comparison).
Foam::scalarList voidageList(const Foam::string& text)
{
    using namespace Foam;
    const std::string allowed =
        "allowed: one or more voidages, each in (0, 1), in parentheses,"
        " e.g. -voidage '(0.4 0.45 0.5)'";
    std::string inner(text);
    const std::size_t open = inner.find('(');
    const std::size_t close = inner.rfind(')');
    if (open != std::string::npos || close != std::string::npos)
    {
        const bool onlySpaceOutside =
            open != std::string::npos && close != std::string::npos
         && open < close
         && inner.find_first_not_of(" \t") == open
         && inner.find_last_not_of(" \t") == close;
        if (!onlySpaceOutside)
        {
            FatalErrorInFunction
                << "Option -voidage '" << text.c_str() << "': unbalanced or"
                << " misplaced parentheses; " << allowed.c_str()
                << exit(FatalError);
        }
        inner = inner.substr(open + 1, close - open - 1);
    }
    DynamicList<scalar> values;
    std::istringstream words(inner);
    for (std::string word; words >> word;)
    {
        double v = 0;
        const bool number = readFiniteNumber(word, v);
        if (!number || !(v > 0 && v < 1))
        {
            FatalErrorInFunction
                << "Option -voidage: '" << word.c_str() << "' is "
                << (number ? "outside (0, 1)" : "not a finite number")
                << "; " << allowed.c_str() << exit(FatalError);
        }
        values.append(v);
    }
    if (values.empty())
    {
        FatalErrorInFunction
            << "Option -voidage: the list is empty; " << allowed.c_str()
            << exit(FatalError);
    }
    return scalarList(std::move(values));
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Minimum fluidization velocities of the case's particles with its"
        " drag model, against the Wen-Yu Umf of the solver's inlet"
    );
    argList::noParallel();
    argList::addOption
    (
        "voidage",
        "list",
        "Voidages of the bed, each in (0, 1) (default '(0.4 0.45 0.5)')"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"
    Sout.precision(8);

    const scalarList voidages
    (
        args.found("voidage")
      ? voidageList(args["voidage"])
      : scalarList({0.4, 0.45, 0.5})
    );

    gasProperties gas(mesh);
    const dpmCloud particles        // no particles: only the settings
    (
        "particles", mesh, gas, g.value(), dpmCloud::startMode::pack
    );
    const fluidizationVelocities& fluid = particles.fluidization();
    const scalar gMag = mag(g.value());
    const wordList& names = particles.classNames();
    const std::vector<int> n(particles.classCounts());
    const scalarList d(particles.classDiameters());
    const scalarList rho(particles.classDensities());

    // The solver's inlet: Wen-Yu for the dictionary's mixture
    scalarList w(d.size());
    scalar mass = 0, volume = 0;
    forAll(d, k)
    {
        const scalar V = n[k]*constant::mathematical::pi*pow3(d[k])/6;
        w[k] = rho[k]*V;
        mass += w[k];
        volume += V;
    }
    forAll(w, k) w[k] /= mass;
    const scalar dMix = fluidization::harmonicMeanDiameter(w, d);
    const scalar wenYu =
        fluidization::wenYuUmf(dMix, mass/volume, gas.rho(), gas.mu(), gMag);
    const scalar U0 = gas.U0(wenYu);

    const dictionary& dict =
        mesh.lookupObject<IOdictionary>("particleProperties");
    Info<< nl << "Drag model " << dict.get<word>("dragModel")
        << "; gas density " << gas.rho() << " kg/m3, viscosity " << gas.mu()
        << " Pa s; g " << gMag << " m/s2" << nl << "Mixture (the dictionary's"
        << " counts):";
    forAll(names, k)
    {
        Info<< ' ' << names[k] << ' ' << n[k] << " x " << d[k]*1e3 << " mm"
            << " (mass fraction " << w[k] << ')';
    }
    Info<< nl << "Wen-Yu Umf " << wenYu << " m/s (harmonic mean diameter "
        << dMix*1e3 << " mm); U0 " << U0 << " m/s ("
        << gas.U0Setting().c_str() << ")" << nl << nl
        << "Superficial gas velocity [m/s] whose drag carries, in a bed of"
        << " the voidage:" << nl << "voidage" << "  Umf(mixture)" << "  U0/Umf";
    forAll(names, k) Info<< "  " << names[k] << "(in mixture)";
    forAll(names, k) Info<< "  " << names[k] << "(alone)";
    Info<< nl;

    for (const scalar eps : voidages)
    {
        const scalar Umf = fluid.mixtureUmf(eps, gMag);
        Info<< eps << "  " << Umf << "  " << U0/Umf;
        forAll(names, k)
        {
            Info<< "  " << fluid.carryingVelocity(k, eps, gMag);
        }
        forAll(names, k)
        {
            Info<< "  " << fluid.carryingVelocity(k, eps, gMag, true);
        }
        Info<< nl;
    }

    particles.formulation().umfBalanceNote(Info, rho);

    Info<< nl << "Terminal velocity [m/s]:";
    forAll(names, k)
    {
        Info<< ' ' << names[k] << ' ' << fluid.terminalVelocity(k, gMag);
    }
    Info<< nl << nl << "End\n" << endl;

    return 0;
}


// ************************************************************************* //
