/*---------------------------------------------------------------------------*\
    dpmFoam2D: soft-sphere CFD-DEM for gas-solid fluidized beds
-------------------------------------------------------------------------------
    SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
    SPDX-License-Identifier: GPL-3.0-or-later
License
    This file is part of dpmFoam2D, free software under the GNU General
    Public License, version 3 or (at your option) any later version;
    see the file LICENSE.
\*---------------------------------------------------------------------------*/

#include "dictionaryScan.H"
#include "dictionaryLexer.H"
#include "error.H"
#include "OSspecific.H"

#include <cctype>
#include <cerrno>
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cfenv>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

using Token = caseChecks::dictionaryToken;
using Lexer = caseChecks::dictionaryLexer;


//- $VAR, ${VAR}, ~ and <case>/<system>/<constant> expanded; false when a
//  variable is not in the environment (a dictionary's own variable)
bool expandName(std::string& name, const fileName& casePath)
{
    std::string out;
    for (std::size_t i = 0; i < name.size(); ++i)
    {
        if (name[i] != '$')
        {
            out += name[i];
            continue;
        }
        const bool braced = i + 1 < name.size() && name[i + 1] == '{';
        const std::size_t start = i + (braced ? 2 : 1);
        std::size_t stop = start;
        if (braced)
        {
            stop = name.find('}', start);
            if (stop == std::string::npos) return false;
        }
        else
        {
            while
            (
                stop < name.size()
             && (std::isalnum(static_cast<unsigned char>(name[stop])) || name[stop] == '_')
            )
            {
                ++stop;
            }
        }
        const char* value = std::getenv(name.substr(start, stop - start).c_str());
        if (!value) return false;
        out += value;
        i = braced ? stop : stop - 1;
    }
    for (const char* tag : {"<case>", "<system>", "<constant>"})
    {
        const std::string t(tag);
        if (out.compare(0, t.size(), t) == 0)
        {
            const std::string dir =
                t == "<case>" ? casePath
              : t == "<system>" ? casePath/"system" : casePath/"constant";
            out = dir + out.substr(t.size());
        }
    }
    if (!out.empty() && out[0] == '~')
    {
        out = home() + out.substr(1);
    }
    name = out;
    return true;
}


class Scanner
{
    const fileName casePath_;
    const std::string caseRoot_;

    //- The files being read, outermost first (canonical paths) and the
    //  lines of their #includes
    std::vector<std::string> stack_;
    std::vector<int> includeLines_;
    label nRead_ = 0;

    //- A path as the user knows it: relative to the case when inside it
    std::string shown(const std::string& path) const
    {
        if (path.compare(0, caseRoot_.size() + 1, caseRoot_ + "/") == 0)
        {
            return path.substr(caseRoot_.size() + 1);
        }
        return path;
    }

    std::string where(const std::string& dictPath, int line) const
    {
        return shown(stack_.back()) + dictPath + " (line "
            + std::to_string(line) + ")";
    }

    void checkNumber
    (
        const Token& t,
        const std::string& keyword,
        const std::string& dictPath
    ) const
    {
        // With traps off: an overflowing conversion raises the
        // floating-point exception OpenFOAM traps (FOAM_SIGFPE)
        std::fenv_t trapping;
        std::feholdexcept(&trapping);
        errno = 0;
        const double value = std::strtod(t.text.c_str(), nullptr);
        const bool outOfRange = errno == ERANGE;
        std::fesetenv(&trapping);
        if (!outOfRange)
        {
            return;
        }
        const std::string what =
            keyword.empty()
          ? "The number " + t.text + " in " + where(dictPath, t.line)
          : "Entry '" + keyword + "' = " + t.text + " in "
            + where(dictPath, t.line);
        if (std::isinf(value))
        {
            FatalErrorInFunction
                << what.c_str() << " is out of the range of a double"
                << " (magnitude up to " << DBL_MAX << "), which OpenFOAM"
                << " cannot read: write a number in that range"
                << exit(FatalError);
        }
        if (std::fabs(value) < DBL_MIN)
        {
            FatalErrorInFunction
                << what.c_str() << " is below the smallest double (magnitude "
                << DBL_MIN << "), which OpenFOAM reads as 0 without a word:"
                << " write 0 or a number in that range" << exit(FatalError);
        }
    }

    //- An #include's file, resolved as OpenFOAM does (relative to the
    //  including file); empty when it names a dictionary variable
    std::string includedFile(const std::string& name) const
    {
        std::string f = name;
        if (!expandName(f, casePath_) || f.empty())
        {
            return "";
        }
        if (f[0] != '/')
        {
            f = fileName(stack_.back()).path()/f;
        }
        return f;
    }

    void directive(const Token& t, Lexer& lex)
    {
        if (t.text == "include" || t.text == "includeIfPresent" || t.text == "sinclude")
        {
            const Token name = lex.next();
            if (name.kind != Token::string && name.kind != Token::word)
            {
                return;     // OpenFOAM names the malformed #include
            }
            const std::string file = includedFile(name.text);
            if (!file.empty() && isFile(file))
            {
                includeLines_.push_back(t.line);
                scanFile(file);
                includeLines_.pop_back();
            }
            return;
        }
        // #includeEtc, #includeFunc, #remove, #inputMode, #calc, ...:
        // their arguments are not entries
        lex.skipLine();
    }

    //- The value of `keyword` up to its ';'; true when it ended the
    //  enclosing dictionary ('}')
    bool value(Lexer& lex, const std::string& keyword, const std::string& dictPath)
    {
        int depth = 0;
        bool opaque = false;
        std::vector<Token> topLevel;
        for (Token t = lex.next(); ; t = lex.next())
        {
            switch (t.kind)
            {
                case Token::end:
                    return true;
                case Token::semicolon:
                    if (depth == 0) return false;
                    break;
                case Token::open:
                    if (t.text == "{" && depth == 0 && topLevel.empty())
                    {
                        block(lex, dictPath + "/" + keyword);
                        return false;
                    }
                    ++depth;
                    break;
                case Token::close:
                    if (depth == 0) return true;
                    --depth;
                    break;
                case Token::directive:
                case Token::verbatim:
                    opaque = true;
                    break;
                case Token::number:
                    checkNumber(t, keyword, dictPath);
                    break;
                default:
                    break;
            }
            if (depth == 0 && t.kind != Token::close)
            {
                topLevel.push_back(t);
            }
            if
            (
                !opaque && depth == 0 && t.kind == Token::word
             && topLevel.size() > 1
             && topLevel[0].kind == Token::number
            )
            {
                std::string held;
                for (const Token& h : topLevel) held += " " + h.text;
                FatalErrorInFunction
                    << "Entry '" << keyword.c_str() << "' in "
                    << where(dictPath, topLevel[0].line).c_str() << " holds '"
                    << held.substr(1).c_str() << "...' where one value is"
                    << " expected: a missing ';' after '"
                    << topLevel[0].text.c_str() << "'? End the entry with ';'"
                    << exit(FatalError);
            }
        }
    }

    //- A list without a keyword (a file of values), after its opening
    //  bracket: its numbers
    void list(Lexer& lex, const std::string& dictPath) const
    {
        for (int depth = 1; depth > 0; )
        {
            const Token t = lex.next();
            switch (t.kind)
            {
                case Token::end: return;
                case Token::open: ++depth; break;
                case Token::close: --depth; break;
                case Token::number: checkNumber(t, "", dictPath); break;
                default: break;
            }
        }
    }

    //- The entries of a dictionary, up to its '}' (or the file's end)
    void block(Lexer& lex, const std::string& dictPath)
    {
        for (Token t = lex.next(); ; t = lex.next())
        {
            switch (t.kind)
            {
                case Token::end:
                case Token::close:
                    return;
                case Token::semicolon:
                case Token::verbatim:
                    break;
                case Token::directive:
                    directive(t, lex);
                    break;
                case Token::open:
                    if (t.text == "{")
                    {
                        block(lex, dictPath);
                    }
                    else
                    {
                        list(lex, dictPath);
                    }
                    break;
                default:
                    if (t.kind == Token::number)
                    {
                        checkNumber(t, "", dictPath);
                    }
                    if (value(lex, t.text, dictPath))
                    {
                        return;
                    }
                    break;
            }
        }
    }

public:

    explicit Scanner(const fileName& casePath)
    :
        casePath_(casePath),
        caseRoot_(canonical(casePath))
    {}

    static std::string canonical(const std::string& path)
    {
        char* real = ::realpath(path.c_str(), nullptr);
        if (!real) return path;
        const std::string result(real);
        std::free(real);
        return result;
    }

    //- Does the file start with a FoamFile header (a dictionary)?
    static bool isDictionary(const std::string& text)
    {
        Lexer lex(text);
        const Token t = lex.next();
        return t.kind == Token::word && t.text == "FoamFile";
    }

    static bool read(const std::string& path, std::string& text)
    {
        std::ifstream is(path, std::ios::binary);
        if (!is) return false;
        std::ostringstream os;
        os << is.rdbuf();
        text = os.str();
        return text.find('\0') == std::string::npos;    // not binary
    }

    void scanFile(const std::string& path)
    {
        const std::string real = canonical(path);
        for (std::size_t k = 0; k < stack_.size(); ++k)
        {
            if (stack_[k] != real) continue;
            std::string chain;
            for (std::size_t j = k; j < stack_.size(); ++j)
            {
                chain += shown(stack_[j]) + " (line "
                    + std::to_string(includeLines_[j]) + ") includes ";
            }
            chain += shown(real);
            FatalErrorInFunction
                << "#include loop: " << chain.c_str() << "; OpenFOAM would"
                << " read them without end: remove the #include that closes"
                << " the loop" << exit(FatalError);
        }
        std::string text;
        if (++nRead_ > 1000 || !read(real, text))
        {
            return;
        }
        stack_.push_back(real);
        Lexer lex(text);
        block(lex, "");
        stack_.pop_back();
    }

    void scanCase()
    {
        // 0/: the initial fields, the one time directory a user edits
        for (const word dir : {"system", "constant", "0"})
        {
            for (const fileName& f : readDir(casePath_/dir, fileName::FILE, false))
            {
                const std::string path = casePath_/dir/f;
                std::string text;
                if (read(path, text) && isDictionary(text))
                {
                    scanFile(path);
                }
            }
        }
    }
};

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

void Foam::caseChecks::dictionaryFiles(const fileName& casePath)
{
    Scanner(casePath).scanCase();
}


// ************************************************************************* //
