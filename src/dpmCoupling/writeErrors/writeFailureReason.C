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

#include "writeFailureReason.H"

#include <fcntl.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>

// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

std::string Foam::writeFailureReason(const fileName& dir)
{
    const fileName probe = dir/".writeProbe";
    const int fd = ::open(probe.c_str(), O_WRONLY|O_CREAT|O_TRUNC, 0666);
    if (fd < 0)
    {
        return std::strerror(errno);
    }
    // A page, so a full disk cannot hide it in a partly used block
    const std::string bytes(4096, '\0');
    int err = 0;
    if (::write(fd, bytes.data(), bytes.size()) < 0 || ::fsync(fd) != 0)
    {
        err = errno;
    }
    if (::close(fd) != 0 && !err)
    {
        err = errno;
    }
    ::unlink(probe.c_str());
    return err ? std::strerror(err) : "unknown reason";
}


// ************************************************************************* //
