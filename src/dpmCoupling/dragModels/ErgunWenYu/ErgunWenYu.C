#include "ErgunWenYu.H"
#include "addToRunTimeSelectionTable.H"
#include "mathematicalConstants.H"
#include "positiveEntry.H"

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
{}


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

    #pragma omp parallel for num_threads(nThreads_) schedule(static)
    forAll(K, i)
    {
        const scalar eps = voidage[i];
        const scalar d = diameter[i];
        const scalar Vp = pi*d*d*d/6;

        K[i] =
            eps < switchVoidage_
          ? ergunK(rho_, mu_, Vp, eps, d, slip[i])
          : wenYuK(rho_, mu_, Vp, eps, d, slip[i]);
    }
}
