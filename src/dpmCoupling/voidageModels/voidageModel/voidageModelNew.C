#include "voidageModel.H"
#include "OStringStream.H"

Foam::autoPtr<Foam::voidageModel> Foam::voidageModel::New
(
    const dictionary& dict,
    const cartesianGrid2D& grid,
    const scalar voidageMin
)
{
    const word key("voidageModel");
    if (!dict.found(key, keyType::LITERAL))
    {
        return
            (*gridConstructorTablePtr_)["discs2D"](grid, voidageMin);
    }

    // The tokens, not a word: `voidageModel 3;` gets the same message
    ITstream& is = dict.lookup(key, keyType::LITERAL);
    const tokenList& tokens = is;
    if (tokens.size() == 1 && tokens[0].isWord())
    {
        auto cstrIter = gridConstructorTablePtr_->cfind(tokens[0].wordToken());
        if (cstrIter.found())
        {
            return cstrIter()(grid, voidageMin);
        }
    }

    OStringStream value;
    forAll(tokens, i)
    {
        value<< (i ? " " : "") << tokens[i];
    }
    FatalIOErrorInFunction(is)
        << "Entry '" << key << "' = " << value.str().c_str() << " in "
        << dict.name() << " is not allowed; allowed: discs2D (disc-area"
        << " fraction and Hoomans' 3D voidage, the paper's, default) or"
        << " slab3D (sphere volume in the cell column of a slab one cell"
        << " thick)" << exit(FatalIOError);

    return nullptr;
}


// ************************************************************************* //
