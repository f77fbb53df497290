#include "voidageModel.H"
#include "choiceEntry.H"

Foam::autoPtr<Foam::voidageModel> Foam::voidageModel::New
(
    const dictionary& dict,
    const cartesianGrid2D& grid,
    const scalar voidageMin
)
{
    const word choice = choiceEntry
    (
        dict, "voidageModel", gridConstructorTablePtr_->sortedToc(), "discs2D",
        "discs2D (disc-area fraction and Hoomans' 3D voidage, the paper's,"
        " default) or slab3D (sphere volume in the cell column of a slab one"
        " cell thick)"
    );
    return (*gridConstructorTablePtr_)[choice](grid, voidageMin);
}


// ************************************************************************* //
