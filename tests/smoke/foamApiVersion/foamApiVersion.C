/*---------------------------------------------------------------------------*\
Application
    foamApiVersion

Description
    Smoke test of the development kit: a trivial application compiled by
    wmake against Debian's OpenFOAM libraries. Prints the API version that
    the libraries report, so a header/library mismatch shows at once.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "foamVersion.H"

using namespace Foam;

int main(int argc, char *argv[])
{
    argList::noBanner();
    argList::noParallel();
    #include "setRootCase.H"

    Info<< "api " << foamVersion::api << nl
        << "patch " << foamVersion::patch.c_str() << nl
        << "label bytes " << sizeof(label) << nl
        << "scalar bytes " << sizeof(scalar) << endl;

    return 0;
}
