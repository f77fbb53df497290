#include "dragModel.H"

namespace Foam
{
    defineTypeNameAndDebug(dragModel, 0);
    defineRunTimeSelectionTable(dragModel, dictionary);
}

Foam::dragModel::dragModel(const scalar rho, const scalar mu)
:
    rho_(rho),
    mu_(mu),
    nThreads_(1)
{}
