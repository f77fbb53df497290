#include "voidageModel.H"

namespace Foam
{
    defineTypeNameAndDebug(voidageModel, 0);
    defineRunTimeSelectionTable(voidageModel, grid);
}


Foam::voidageModel::voidageModel
(
    const cartesianGrid2D& grid,
    const scalar voidageMin
)
:
    grid_(grid),
    voidageMin_(voidageMin)
{}


// ************************************************************************* //
