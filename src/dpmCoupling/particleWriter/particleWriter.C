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

#include "particleWriter.H"
#include "caseChecks.H"
#include "OSspecific.H"
#include "IOstreams.H"
#include "OStringStream.H"
#include "faultInjection.H"
#include "dem/Facade.hpp"

#include <hdf5.h>
#include <fcntl.h>
#include <unistd.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <vector>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- Write one dataset of shape [n] or [n, width] (in memory: no disk error)
template<class T>
bool writeDataset
(
    hid_t file, const char* name, hid_t type,
    const std::vector<T>& data, const hsize_t n, const hsize_t width
)
{
    const hsize_t dims[2] = {n, width};
    const hid_t space = H5Screate_simple(width > 1 ? 2 : 1, dims, nullptr);
    const hid_t set = H5Dcreate2
    (
        file, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT
    );
    const bool ok =
        space >= 0 && set >= 0
     && (n == 0 || H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) >= 0);
    if (set >= 0) H5Dclose(set);
    if (space >= 0) H5Sclose(space);
    return ok;
}


//- Write bytes to file as a whole: to file.partial, then renamed, so a
//  kill or a full disk never leaves a part of it under its name. A write
//  error stops the run naming the file and the system's reason. The fault
//  points <faultPoint>, .part (half the bytes written) and .rename lie on
//  the way (faultInjection.H).
void writeWhole
(
    const Foam::fileName& file,
    const char* data,
    const size_t size,
    const char* faultPoint
)
{
    using namespace Foam;
    faultInjection::at(faultPoint);

    const fileName partial = file + ".partial";
    const auto failed = [&]()
    {
        const int err = errno;
        ::unlink(partial.c_str());      // leave no part behind, free the space
        FatalErrorInFunction
            << "Cannot write " << file << ": " << std::strerror(err)
            << exit(FatalError);
    };

    // A fresh file, never through a link left at its name
    ::unlink(partial.c_str());
    const int fd =
        ::open(partial.c_str(), O_WRONLY|O_CREAT|O_EXCL|O_NOFOLLOW, 0666);
    if (fd < 0) failed();
    const auto writeAll = [&](size_t done, const size_t end)
    {
        while (done < end)
        {
            const ssize_t w = ::write(fd, data + done, end - done);
            if (w < 0)
            {
                if (errno == EINTR) continue;
                const int err = errno;
                ::close(fd);
                errno = err;
                failed();
            }
            done += size_t(w);
        }
    };
    writeAll(0, size/2);
    faultInjection::at(faultPoint, "part");
    writeAll(size/2, size);
    if (::close(fd) != 0) failed();
    faultInjection::at(faultPoint, "rename");
    if (std::rename(partial.c_str(), file.c_str()) != 0) failed();
}


//- Whether the HDF5 file has a dataset of that name (false if unreadable)
bool hasDataset(const Foam::fileName& file, const char* name)
{
    bool found = false;
    H5E_BEGIN_TRY
    {
        const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        if (h5 >= 0)
        {
            found = H5Lexists(h5, name, H5P_DEFAULT) > 0;
            H5Fclose(h5);
        }
    }
    H5E_END_TRY
    return found;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleWriter::particleWriter
(
    const fileName& caseDir,
    const scalar depth,
    const scalar startTime
)
:
    dir_(caseDir/"particles"),
    depth_(depth)
{
    mkDir(dir_);
    caseChecks::writesInsideCase(dir_, caseDir, "The particle writer");

    // Files from before a restart are listed up to the start time; later
    // ones belong to the run being replaced and are overwritten as it goes.
    for (const fileName& f : readDir(dir_, fileName::FILE))
    {
        if (f.ext() != "h5") continue;
        const word name(f.lessExt());
        scalar t;
        if (readScalar(name, t) && t <= startTime*(1 + 1e-12) + 1e-12)
        {
            times_.push_back({t, name, hasDataset(dir_/f, "voidage")});
        }
    }
    std::sort
    (
        times_.begin(), times_.end(),
        [](const indexedFile& a, const indexedFile& b)
        { return a.time < b.time; }
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::particleWriter::write
(
    const dem::Simulation& particles,
    const scalarField& voidage,
    const vectorField& gasVelocity,
    const scalar t,
    const word& timeName
)
{
    const hsize_t n = particles.size();
    std::vector<float> position(3*n), velocity(3*n), omega(n), diameter(n);
    std::vector<signed char> classIndex(n);
    std::vector<int> id(n);
    const bool slab = particles.settings().dimension == 3;
    for (hsize_t i = 0; i < n; ++i)
    {
        position[3*i] = float(particles.x()[i]);
        position[3*i + 1] = float(particles.y()[i]);
        position[3*i + 2] = float(0.5*depth_);
        velocity[3*i] = float(particles.vx()[i]);
        velocity[3*i + 1] = float(particles.vy()[i]);
        velocity[3*i + 2] = 0;
        omega[i] = float(particles.omega()[i]);
        diameter[i] = float(particles.diameter()[i]);
        classIndex[i] = static_cast<signed char>(particles.classIndex()[i]);
        id[i] = int(particles.id()[i]);
    }
    // The slab mode's spheres: their real z, vz and spin vector
    std::vector<float> spin(slab ? 3*n : 0);
    for (hsize_t i = 0; slab && i < n; ++i)
    {
        position[3*i + 2] = float(particles.z()[i]);
        velocity[3*i + 2] = float(particles.vz()[i]);
        spin[3*i] = float(particles.omegaX()[i]);
        spin[3*i + 1] = float(particles.omegaY()[i]);
        spin[3*i + 2] = float(particles.omegaZ()[i]);
    }

    // The file is made in memory (HDF5's core driver) and written as a
    // whole: a disk error is then one plain write error, named with its
    // file, and leaves HDF5 with no half-closed file at exit
    const fileName final = file(timeName);
    const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_fapl_core(fapl, 1 << 20, false);
    const hid_t h5 =
        H5Fcreate(final.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    H5Pclose(fapl);
    if (h5 < 0)
    {
        FatalErrorInFunction
            << "Cannot make the HDF5 image of " << final << exit(FatalError);
    }

    bool ok = true;
    const hid_t scalarSpace = H5Screate(H5S_SCALAR);
    const hid_t attr = H5Acreate2
    (
        h5, "time", H5T_NATIVE_DOUBLE, scalarSpace, H5P_DEFAULT, H5P_DEFAULT
    );
    const double time = t;
    ok = ok && attr >= 0 && H5Awrite(attr, H5T_NATIVE_DOUBLE, &time) >= 0;
    if (attr >= 0) H5Aclose(attr);
    H5Sclose(scalarSpace);

    ok = ok && writeDataset(h5, "position", H5T_NATIVE_FLOAT, position, n, 3);
    ok = ok && writeDataset(h5, "velocity", H5T_NATIVE_FLOAT, velocity, n, 3);
    ok = ok && writeDataset(h5, "omega", H5T_NATIVE_FLOAT, omega, n, 1);
    ok = ok && (!slab || writeDataset(h5, "spin", H5T_NATIVE_FLOAT, spin, n, 3));
    ok = ok && writeDataset(h5, "diameter", H5T_NATIVE_FLOAT, diameter, n, 1);
    ok = ok && writeDataset(h5, "class", H5T_NATIVE_SCHAR, classIndex, n, 1);
    ok = ok && writeDataset(h5, "id", H5T_NATIVE_INT, id, n, 1);
    const bool gasFields =
        voidage.size() == label(n) && gasVelocity.size() == label(n);
    if (ok && gasFields)
    {
        std::vector<float> eps(n), u(3*n);
        for (hsize_t i = 0; i < n; ++i)
        {
            eps[i] = float(voidage[i]);
            for (int k = 0; k < 3; ++k) u[3*i + k] = float(gasVelocity[i][k]);
        }
        ok = ok && writeDataset(h5, "voidage", H5T_NATIVE_FLOAT, eps, n, 1);
        ok = ok && writeDataset(h5, "gasVelocity", H5T_NATIVE_FLOAT, u, n, 3);
    }

    std::vector<char> image;
    if (ok && H5Fflush(h5, H5F_SCOPE_GLOBAL) >= 0)
    {
        const ssize_t size = H5Fget_file_image(h5, nullptr, 0);
        if (size > 0)
        {
            image.resize(size);
            ok = H5Fget_file_image(h5, image.data(), size) == size;
        }
        else
        {
            ok = false;
        }
    }
    else
    {
        ok = false;
    }
    if (H5Fclose(h5) < 0 || !ok)
    {
        FatalErrorInFunction
            << "Cannot make the HDF5 image of " << final << exit(FatalError);
    }
    writeWhole(final, image.data(), image.size(), "particleWrite");

    // Replace a later entry of an earlier run; keep the list in time order
    while (times_.size() && times_.back().time >= t*(1 - 1e-12) - 1e-12)
    {
        times_.pop_back();
    }
    times_.push_back({t, timeName, gasFields});
    writeIndex(particles);
}


bool Foam::particleWriter::hasGasFields(const word& timeName) const
{
    for (const indexedFile& f : times_)
    {
        if (f.name == timeName) return f.gasFields;
    }
    return false;
}


void Foam::particleWriter::writeIndex(const dem::Simulation& particles) const
{
    const label n = particles.size();
    const bool slab = particles.settings().dimension == 3;
    OStringStream os;
    {
        os  << "<?xml version=\"1.0\" ?>\n"
            << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
            << "<Xdmf Version=\"2.0\">\n<Domain>\n"
            << "<Grid Name=\"particles\" GridType=\"Collection\""
            << " CollectionType=\"Temporal\">\n";

        const auto item =
            [&](const word& h5, const char* set, const char* type,
                const int precision, const label width)
            {
                os  << "    <DataItem Dimensions=\"" << n;
                if (width > 1) os << ' ' << width;
                os  << "\" NumberType=\"" << type << "\" Precision=\""
                    << precision << "\" Format=\"HDF\">" << h5 << ".h5:/"
                    << set << "</DataItem>\n";
            };
        const auto attribute =
            [&](const word& h5, const char* set, const char* center,
                const char* kind, const char* type, const int precision,
                const label width)
            {
                os  << "   <Attribute Name=\"" << set << "\" AttributeType=\""
                    << kind << "\" Center=\"" << center << "\">\n";
                item(h5, set, type, precision, width);
                os  << "   </Attribute>\n";
            };

        // The time as its name: a restarted run lists the same values
        for (const indexedFile& f : times_)
        {
            const word& h5 = f.name;
            os  << "  <Grid Name=\"particles_" << h5
                << "\" GridType=\"Uniform\">\n"
                << "   <Time Value=\"" << h5 << "\"/>\n"
                << "   <Topology TopologyType=\"Polyvertex\" NumberOfElements=\""
                << n << "\"/>\n"
                << "   <Geometry GeometryType=\"XYZ\">\n";
            item(h5, "position", "Float", 4, 3);
            os  << "   </Geometry>\n";
            attribute(h5, "velocity", "Node", "Vector", "Float", 4, 3);
            attribute(h5, "omega", "Node", "Scalar", "Float", 4, 1);
            if (slab)
            {
                attribute(h5, "spin", "Node", "Vector", "Float", 4, 3);
            }
            attribute(h5, "diameter", "Node", "Scalar", "Float", 4, 1);
            attribute(h5, "class", "Node", "Scalar", "Char", 1, 1);
            attribute(h5, "id", "Node", "Scalar", "Int", 4, 1);
            if (f.gasFields)
            {
                attribute(h5, "voidage", "Node", "Scalar", "Float", 4, 1);
                attribute(h5, "gasVelocity", "Node", "Vector", "Float", 4, 3);
            }
            os  << "  </Grid>\n";
        }
        os  << "</Grid>\n</Domain>\n</Xdmf>\n";
    }
    const std::string text = os.str();
    writeWhole(dir_/"particles.xdmf", text.data(), text.size(), "xdmfWrite");
}
