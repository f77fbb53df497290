// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
// dpmConvertState <in> [<out>]: a DEM state file (a bed or a restart's dem.state) of an
// older version written in its engine's current version (dem::convertState). Without
// <out> it converts in place and keeps the original beside it as <in>.version<N>.

#include "dem/Error.hpp"
#include "dem/StateConversion.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

namespace {

int usage()
{
    std::cerr << "Usage: " << dem::stateConverter << " <in> [<out>]\n"
              << "  Writes a DEM state file of an older version (2D "
              << dem::oldestDiscStateVersion << "-" << dem::discStateVersion - 1 << ", slab "
              << dem::oldestSlabStateVersion << "-" << dem::slabStateVersion - 1
              << ") in the current version (2D " << dem::discStateVersion << ", slab "
              << dem::slabStateVersion << ").\n"
              << "  Without <out>: in place, the original kept as <in>.version<N>.\n"
              << "  Settings the older file did not record are written as it ran: the\n"
              << "  contact law of its run record (else linear), tangentialDampingRatio 1,\n"
              << "  no rolling friction, no Young's moduli or Poisson's ratios; a run with\n"
              << "  other values refuses the converted file naming them.\n";
    return 1;
}

} // namespace

int main(int argc, char** argv)
{
    const std::string first = argc > 1 ? argv[1] : "";
    if (argc < 2 || argc > 3 || first == "-help" || first == "--help") return usage();
    const std::string in = argv[1];
    const bool inPlace = argc == 2;
    const std::string out = inPlace ? in : argv[2];
    try {
        namespace fs = std::filesystem;
        // The conversion writes to a temporary first: the backup is made only once it is whole.
        const std::string converted = inPlace ? in + ".converting" : out;
        const dem::StateConversion c = dem::convertState(in, converted);
        const char* engine = c.dimension == 2 ? "2D" : "slab";
        if (c.fromVersion == c.toVersion) {
            std::cout << "'" << in << "' is a " << engine << " state of the current version ("
                      << c.toVersion << "): nothing to convert, nothing written\n";
            return 0;
        }
        if (inPlace) {
            const std::string backup = in + ".version" + std::to_string(c.fromVersion);
            // Any failure from here leaves the original as it was and no temporary behind
            auto refuse = [&](const std::string& why) {
                std::error_code ignored;
                fs::remove(converted, ignored);
                throw dem::Error("cannot keep the original '" + in + "' as '" + backup + "': "
                                 + why + "; nothing converted");
            };
            std::error_code error;
            const fs::file_status status = fs::symlink_status(backup, error);
            if (fs::exists(status) && !fs::is_regular_file(status)) {
                refuse("that name is a " + std::string(fs::is_directory(status) ? "directory"
                                                                                 : "special file")
                       + " (move it away, or convert to another file: " + dem::stateConverter
                       + " <in> <out>)");
            }
            fs::copy_file(in, backup, fs::copy_options::overwrite_existing, error);
            if (error) refuse(error.message());
            fs::rename(converted, in, error);
            if (error) refuse("the converted file could not replace it: " + error.message());
            std::cout << "Kept the original as '" << backup << "'\n";
        }
        std::cout << "Converted '" << in << "' (" << engine << " state version " << c.fromVersion
                  << ") to '" << out << "' (version " << c.toVersion << ")\n";
        std::istringstream notes(c.notes);
        for (std::string line; std::getline(notes, line);) std::cout << "  Note: " << line << "\n";
        return 0;
    } catch (const std::exception& e) {
        std::cerr << dem::stateConverter << ": " << e.what() << "\n";
        return 1;
    }
}
