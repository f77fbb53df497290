#include "ErgunWenYu.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "positiveEntry.H"
#include "knownEntries.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(ErgunWenYu, 0);
    addToRunTimeSelectionTable(dragModel, ErgunWenYu, dictionary);
}
}


Foam::dragModels::ErgunWenYu::ErgunWenYu
(
    const dictionary& coeffs,
    const scalar rho,
    const scalar mu
)
:
    dragModel(rho, mu),
    switchVoidage_
    (
        boundedEntryOrDefault(coeffs, "switchVoidage", 0.8, 0, 1, true)
    )
{
    checkKnownEntries
    (
        coeffs, {"switchVoidage"},
        "constant/particleProperties/" + typeName + "Coeffs"
    );
}


void Foam::dragModels::ErgunWenYu::dragCoefficient
(
    const scalarField& voidage,
    const scalarField& diameter,
    const scalarField& slip,
    const particleMixture&,
    scalarField& K
) const
{
    const scalar pi = constant::mathematical::pi;

    forAll(K, i)
    {
        const scalar eps = voidage[i];
        const scalar d = diameter[i];
        const scalar Vp = pi*d*d*d/6;

        if (eps < switchVoidage_)
        {
            K[i] = Vp*
            (
                150*(1 - eps)*mu_/(eps*eps*d*d)
              + 1.75*rho_*slip[i]/(eps*d)
            );
        }
        else
        {
            // C_D |u-v| written without dividing by Re, finite at zero slip
            const scalar Re = rho_*d*eps*slip[i]/mu_;
            const scalar CdSlip =
                Re < 1000
              ? 24*mu_/(rho_*d*eps)*(1 + 0.15*std::pow(Re, 0.687))
              : 0.44*slip[i];
            K[i] = Vp*0.75*CdSlip*rho_/d*std::pow(eps, -2.65);
        }
    }
}
