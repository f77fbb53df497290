#include "GidaspowBlend.H"
#include "knownEntries.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"

namespace Foam
{
namespace dragModels
{
    defineTypeNameAndDebug(GidaspowBlend, 0);
    addToRunTimeSelectionTable(dragModel, GidaspowBlend, dictionary);
}
}


Foam::dragModels::GidaspowBlend::GidaspowBlend
(
    const dictionary& coeffs,
    const scalar rho,
    const scalar mu
)
:
    dragModel(rho, mu)
{
    // No coefficients: any entry of <type>Coeffs is a mistake
    checkKnownEntries
    (
        coeffs, wordList(),
        "constant/particleProperties/" + typeName + "Coeffs"
    );
}


void Foam::dragModels::GidaspowBlend::dragCoefficient
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

        const scalar ergun =
            150*(1 - eps)*mu_/(eps*eps*d*d) + 1.75*rho_*slip[i]/(eps*d);

        // C_D |u-v| written without dividing by Re, finite at zero slip
        const scalar Re = rho_*d*eps*slip[i]/mu_;
        const scalar CdSlip =
            Re < 1000
          ? 24*mu_/(rho_*d*eps)*(1 + 0.15*std::pow(Re, 0.687))
          : 0.44*slip[i];
        const scalar wenYu = 0.75*CdSlip*rho_/d*std::pow(eps, -2.65);

        // Weight of Ergun: 1 in the dense bed, 0 in the dilute gas
        const scalar phi = 0.5 + std::atan(262.5*(0.8 - eps))/pi;

        K[i] = Vp*((1 - phi)*wenYu + phi*ergun);
    }
}
