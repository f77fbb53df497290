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

#include "caseLock.H"
#include "error.H"
#include "OSspecific.H"

#include <cerrno>
#include <climits>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

const char* const Foam::caseLock::lockFileName = ".dpmLock";


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

int Foam::caseLock::inheritedDescriptor() const
{
    const char* value = std::getenv("DPMFOAM2D_LOCK_FD");
    if (!value || !*value) return -1;
    char* end = nullptr;
    const long fd = std::strtol(value, &end, 10);
    struct stat inherited, own;
    if
    (
        *end || fd < 0
     || ::fstat(int(fd), &inherited) != 0
     || ::lstat(file_.c_str(), &own) != 0
     || inherited.st_dev != own.st_dev || inherited.st_ino != own.st_ino
    )
    {
        return -1;      // not this directory's lock: take one of our own
    }
    return int(fd);
}


void Foam::caseLock::refuseNotRegular(const char* what) const
{
    FatalErrorInFunction
        << "The lock file " << file_ << " is " << what << "; a lock must be"
        << " a regular file that the run makes itself (one run a directory):"
        << " remove it and start again" << exit(FatalError);
}


Foam::string Foam::caseLock::holder() const
{
    char line[512] = {};
    const ssize_t n = ::pread(fd_, line, sizeof(line) - 1, 0);
    std::string text(line, n > 0 ? size_t(n) : 0);
    const auto eol = text.find('\n');
    if (eol != std::string::npos) text.erase(eol);
    return text.empty() ? string("a process starting up") : string(text);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::caseLock::caseLock
(
    const fileName& dir,
    const word& application,
    const bool optional
)
:
    file_(dir/lockFileName),
    fd_(inheritedDescriptor())
{
    if (fd_ < 0)
    {
        // Read-only: a file open for writing would keep its file system
        // from being remounted read-only (flock needs no write access).
        // Never through a link: the holder line would be written into
        // whatever file the link names
        fd_ = ::open
        (
            file_.c_str(),
            O_RDONLY | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK,
            0644
        );
        if (fd_ < 0 && (errno == ELOOP || errno == EISDIR))
        {
            refuseNotRegular
            (
                errno == ELOOP ? "a symbolic link" : "not a regular file"
            );
        }
    }
    if (fd_ < 0 && optional)
    {
        return;
    }
    if (fd_ < 0)
    {
        FatalErrorInFunction
            << "Cannot make the lock file " << file_ << ": "
            << std::strerror(errno) << exit(FatalError);
    }
    struct stat opened;
    if (::fstat(fd_, &opened) != 0 || !S_ISREG(opened.st_mode))
    {
        refuseNotRegular("not a regular file");
    }

    // A few tries over 0.2 s: a tool that only looks whether the lock is
    // held (dpmStudy -status) holds it for an instant
    bool locked = false;
    for (int attempt = 0; attempt < 10 && !locked; ++attempt)
    {
        locked = (::flock(fd_, LOCK_EX | LOCK_NB) == 0);
        if (!locked && errno != EWOULDBLOCK && errno != EINTR)
        {
            FatalErrorInFunction
                << "Cannot lock " << file_ << ": " << std::strerror(errno)
                << exit(FatalError);
        }
        if (!locked)
        {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
    }
    if (!locked)
    {
        FatalErrorInFunction
            << application.c_str() << ": the directory " << dir << " is in"
            << " use by " << holder().c_str() << ", which holds the lock "
            << file_ << "; two runs there would overwrite each other's"
            << " files: wait for it to end, or stop it" << exit(FatalError);
    }

    char started[64];
    const std::time_t now = std::time(nullptr);
    std::strftime
    (
        started, sizeof(started), "%Y-%m-%d %H:%M:%S UTC", std::gmtime(&now)
    );
    const std::string line =
        std::string(application) + " (pid " + std::to_string(::getpid())
      + " on " + hostName() + ", started " + started + ")\n";
    // Written through a descriptor of the very file locked (the name may
    // have been replaced since), truncated only once that is known
    const int out =
        ::open(file_.c_str(), O_WRONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    struct stat held, target;
    const bool sameFile =
        out >= 0 && ::fstat(out, &target) == 0 && ::fstat(fd_, &held) == 0
     && target.st_dev == held.st_dev && target.st_ino == held.st_ino;
    const bool written =
        sameFile && ::ftruncate(out, 0) == 0
     && ::pwrite(out, line.data(), line.size(), 0) == ssize_t(line.size());
    if (out >= 0) ::close(out);     // the lock stays with fd_
    if (!written)
    {
        WarningInFunction
            << "Cannot write the holder into " << file_ << ": "
            << std::strerror(errno) << " (the lock is held)" << endl;
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::caseLock::~caseLock()
{
    if (fd_ >= 0)
    {
        ::close(fd_);
    }
}


Foam::autoPtr<Foam::caseLock> Foam::caseLock::outsideCase
(
    const fileName& dir,
    const fileName& caseDir,
    const word& application
)
{
    // Absolute paths with links resolved ("" for a directory that is missing)
    const auto resolved = [](const fileName& d)
    {
        char buffer[PATH_MAX];
        return ::realpath(d.c_str(), buffer) ? fileName(buffer) : fileName();
    };
    const fileName target = resolved(dir);
    const fileName root = resolved(caseDir);
    if (target.empty() || target == root || target.starts_with(root + "/"))
    {
        return nullptr;
    }
    // optional: a directory that takes no file is the writer's to name
    return autoPtr<caseLock>(new caseLock(target, application, true));
}


// ************************************************************************* //
