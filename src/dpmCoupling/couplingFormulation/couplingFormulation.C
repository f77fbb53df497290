#include "couplingFormulation.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::couplingFormulation Foam::readCouplingFormulation
(
    const dictionary& dict
)
{
    const word key("formulation");
    if (!dict.found(key, keyType::LITERAL))
    {
        return couplingFormulation::B;
    }

    // The tokens, not a word: `formulation 1;` gets the same message
    ITstream& is = dict.lookup(key, keyType::LITERAL);
    const tokenList& tokens = is;
    if (tokens.size() == 1 && tokens[0].isWord())
    {
        if (tokens[0].wordToken() == "A") return couplingFormulation::A;
        if (tokens[0].wordToken() == "B") return couplingFormulation::B;
    }

    OStringStream value;
    forAll(tokens, i)
    {
        value<< (i ? " " : "") << tokens[i];
    }
    FatalIOErrorInFunction(is)
        << "Entry '" << key << "' = " << value.str().c_str() << " in "
        << dict.name()
        << " is not allowed; allowed: B (the gas sees the whole pressure"
        << " gradient, the paper's, default) or A (particles also feel"
        << " -V_p grad p, the gas eps grad p)" << exit(FatalIOError);

    return couplingFormulation::B;
}


Foam::string Foam::formulationDescription(const couplingFormulation f)
{
    if (f == couplingFormulation::A)
    {
        return
            "formulation A (Zhou et al. 2010 set I): particles feel the"
            " drag eps_g K_B (u - v) and the pressure-gradient force"
            " -V_p grad p; the gas carries eps_g grad p and the drag only";
    }
    return
        "formulation B (the paper's, Zhou et al. 2010 set II): the gas"
        " sees the whole pressure gradient; particles feel the drag"
        " K_B (u - v) and the buoyancy -rho_g V_p g";
}


// ************************************************************************* //
