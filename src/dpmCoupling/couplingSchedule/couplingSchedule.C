#include "couplingSchedule.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::couplingSchedule Foam::readCouplingSchedule(const dictionary& dict)
{
    const word key("couplingSchedule");
    if (!dict.found(key, keyType::LITERAL))
    {
        return couplingSchedule::sequential;
    }

    ITstream& is = dict.lookup(key, keyType::LITERAL);
    const tokenList& tokens = is;
    if (tokens.size() == 1 && tokens[0].isWord())
    {
        const word& w = tokens[0].wordToken();
        if (w == "sequential") return couplingSchedule::sequential;
        if (w == "concurrent") return couplingSchedule::concurrent;
    }

    OStringStream value;
    forAll(tokens, i)
    {
        value<< (i ? " " : "") << tokens[i];
    }
    FatalIOErrorInFunction(is)
        << "Entry '" << key << "' = " << value.str().c_str() << " in "
        << dict.name() << " is not allowed; allowed: sequential (the gas"
        << " after the particles, default) or concurrent (the gas beside the"
        << " particles on a thread of its own, one CFD step behind them)"
        << exit(FatalIOError);

    return couplingSchedule::sequential;
}


Foam::string Foam::scheduleDescription(const couplingSchedule s)
{
    if (s == couplingSchedule::concurrent)
    {
        return
            "schedule concurrent: the gas advances beside the particles, on"
            " a thread of its own, with their voidage and reaction of the"
            " step before (docs/model.md)";
    }
    return
        "schedule sequential: the particles advance, then the gas with"
        " their new voidage and reaction";
}


// ************************************************************************* //
