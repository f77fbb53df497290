// SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dem/Facade.hpp"
#include "dem/SlabSystem.hpp"
#include "dem/System.hpp"

#include <utility>


namespace dem {

namespace {

Eigen::Vector3d vec(const Vector3& v) { return {v.x, v.y, v.z}; }

} // namespace

Simulation::Simulation(const Settings& settings)
{
    if (settings.dimension == 3) {
        slab_ = std::make_unique<SlabSystem>(settings);
    } else {
        system_ = std::make_unique<System>(settings);   // validates, names a bad dimension
    }
}
Simulation::~Simulation() = default;

SlabSystem& Simulation::slab(const char* what) const
{
    if (!slab_) {
        throw Error(std::string(what) + " is of the slab mode (dimension 3); this simulation "
                    "has dimension 2");
    }
    return *slab_;
}

template <class F> decltype(auto) Simulation::onEngine(F&& f)
{
    if (slab_) return f(*slab_);
    return f(*system_);
}

template <class F> decltype(auto) Simulation::onEngine(F&& f) const
{
    if (slab_) return f(std::as_const(*slab_));
    return f(std::as_const(*system_));
}

// A member called on whichever engine is set, its result as the engine returns it.
#define DEM_ON_ENGINE(call) onEngine([&](auto& e) -> decltype(auto) { return e.call; })

void Simulation::packRandom(const std::vector<int>& countPerClass, const Box& region, std::uint64_t seed)
{
    DEM_ON_ENGINE(packRandom(countPerClass, region, seed));
}

double Simulation::packBed(const BedRecipe& recipe, const SettleProgress& progress)
{
    return DEM_ON_ENGINE(packBed(recipe, progress));
}

void Simulation::addParticle(int classIndex, double x, double y, double vx, double vy, double omega)
{
    if (slab_) {
        throw Error("addParticle(class, x, y, ...) places a disc; the slab mode (dimension 3) "
                    "takes a position with z");
    }
    system_->addParticle(classIndex, x, y, vx, vy, omega);
}

void Simulation::addParticle(int classIndex, const Vector3& position, const Vector3& velocity,
                             const Vector3& spin)
{
    slab("addParticle with z").addParticle(classIndex, vec(position), vec(velocity), vec(spin));
}

double Simulation::settle(double maxTime, double keTolerance, const SettleProgress& progress)
{
    return DEM_ON_ENGINE(settle(maxTime, keTolerance, progress));
}
std::size_t Simulation::size() const
{
    return DEM_ON_ENGINE(particles().size());
}
const Settings& Simulation::settings() const
{
    return DEM_ON_ENGINE(settings());
}

// Arrays of both engines under one name: the slab's if present, else the discs'.
#define DEM_ARRAY(slabArray, discArray) \
    (slab_ ? slab_->particles().slabArray.data() : system_->particles().discArray.data())

const double* Simulation::x() const { return DEM_ARRAY(x, x); }
const double* Simulation::y() const { return DEM_ARRAY(y, y); }
const double* Simulation::vx() const { return DEM_ARRAY(vx, vx); }
const double* Simulation::vy() const { return DEM_ARRAY(vy, vy); }
const double* Simulation::omega() const { return DEM_ARRAY(wz, omega); }
const double* Simulation::diameter() const { return DEM_ARRAY(diameter, diameter); }
const double* Simulation::mass() const { return DEM_ARRAY(mass, mass); }
const int* Simulation::classIndex() const { return DEM_ARRAY(classIndex, classIndex); }
const std::int64_t* Simulation::id() const { return DEM_ARRAY(id, id); }
const double* Simulation::z() const { return slab("z").particles().z.data(); }
const double* Simulation::vz() const { return slab("vz").particles().vz.data(); }
const double* Simulation::omegaX() const { return slab("omegaX").particles().wx.data(); }
const double* Simulation::omegaY() const { return slab("omegaY").particles().wy.data(); }
const double* Simulation::omegaZ() const { return omega(); }

double* Simulation::dragCoefficient() { return DEM_ARRAY(dragCoefficient, dragCoefficient); }
double* Simulation::gasVelocityX() { return DEM_ARRAY(gasVx, gasVx); }
double* Simulation::gasVelocityY() { return DEM_ARRAY(gasVy, gasVy); }
double* Simulation::extraForceX() { return DEM_ARRAY(extraFx, extraFx); }
double* Simulation::extraForceY() { return DEM_ARRAY(extraFy, extraFy); }
double* Simulation::gasVelocityZ() { return slab("gasVelocityZ").particles().gasVz.data(); }
double* Simulation::extraForceZ() { return slab("extraForceZ").particles().extraFz.data(); }

void Simulation::advance(double dtOuter) { DEM_ON_ENGINE(advance(dtOuter)); }
void Simulation::sortByCell() { DEM_ON_ENGINE(sortByCell()); }

const double* Simulation::meanVelocityX() const { return DEM_ARRAY(meanVx, meanVx); }
const double* Simulation::meanVelocityY() const { return DEM_ARRAY(meanVy, meanVy); }
const double* Simulation::meanFluidForceX() const { return DEM_ARRAY(meanFluidX, meanFluidX); }
const double* Simulation::meanFluidForceY() const { return DEM_ARRAY(meanFluidY, meanFluidY); }
const double* Simulation::meanVelocityZ() const { return slab("meanVelocityZ").particles().meanVz.data(); }
const double* Simulation::meanFluidForceZ() const
{
    return slab("meanFluidForceZ").particles().meanFluidZ.data();
}

#undef DEM_ARRAY

double Simulation::time() const { return DEM_ON_ENGINE(time()); }
std::int64_t Simulation::stepCount() const { return DEM_ON_ENGINE(stepCount()); }
double Simulation::kineticEnergy() const { return DEM_ON_ENGINE(kineticEnergy()); }
double Simulation::timeStepBound() const
{
    // Eq. 7 for the smallest particle: its mass is a sphere's in both modes.
    return slab_ ? dem::timeStepBound(slab_->settings()) : system_->timeStepBound();
}
std::size_t Simulation::contactCount() const { return DEM_ON_ENGINE(contactCount()); }
double Simulation::elasticEnergy() const { return DEM_ON_ENGINE(elasticEnergy()); }
double Simulation::maxOverlap() const { return DEM_ON_ENGINE(maxOverlap()); }
std::int64_t Simulation::neighbourListBuilds() const { return DEM_ON_ENGINE(neighbourListBuilds()); }
double Simulation::neighbourSkin() const { return DEM_ON_ENGINE(neighbourSkin()); }
std::int64_t Simulation::stepsOnOneThread() const { return DEM_ON_ENGINE(threadChooser().callsOnOne()); }
std::int64_t Simulation::stepsOnAllThreads() const { return DEM_ON_ENGINE(threadChooser().callsOnAll()); }
std::int64_t Simulation::threadHoldsCutShort() const { return DEM_ON_ENGINE(threadChooser().holdsCutShort()); }
std::int64_t Simulation::threadTrialsSkipped() const { return DEM_ON_ENGINE(threadChooser().trialsSkipped()); }
int Simulation::nextStepThreads() const { return DEM_ON_ENGINE(nextStepThreads()); }
std::size_t Simulation::memoryBytes() const { return DEM_ON_ENGINE(memoryBytes()); }

void Simulation::save(const std::string& path) const { DEM_ON_ENGINE(save(path)); }
void Simulation::load(const std::string& path) { DEM_ON_ENGINE(load(path)); }
bool Simulation::loadBed(const std::string& path, const BedRecipe& recipe)
{
    return DEM_ON_ENGINE(loadBed(path, recipe));
}
const BedRecipe* Simulation::recipe() const { return DEM_ON_ENGINE(recipe()); }
const std::string& Simulation::runRecord() const { return DEM_ON_ENGINE(runRecord()); }
void Simulation::setRunRecord(const std::string& record) { DEM_ON_ENGINE(setRunRecord(record)); }

#undef DEM_ON_ENGINE

} // namespace dem
