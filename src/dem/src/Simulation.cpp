#include "dem/Facade.hpp"
#include "dem/System.hpp"

namespace dem {

Simulation::Simulation(const Settings& settings) : system_(std::make_unique<System>(settings)) {}
Simulation::~Simulation() = default;

void Simulation::packRandom(const std::vector<int>& countPerClass, const Box& region, std::uint64_t seed)
{
    system_->packRandom(countPerClass, region, seed);
}

double Simulation::packBed(const BedRecipe& recipe) { return system_->packBed(recipe); }

void Simulation::addParticle(int classIndex, double x, double y, double vx, double vy, double omega)
{
    system_->addParticle(classIndex, x, y, vx, vy, omega);
}

double Simulation::settle(double maxTime, double keTolerance) { return system_->settle(maxTime, keTolerance); }
std::size_t Simulation::size() const { return system_->particles().size(); }
const Settings& Simulation::settings() const { return system_->settings(); }

const double* Simulation::x() const { return system_->particles().x.data(); }
const double* Simulation::y() const { return system_->particles().y.data(); }
const double* Simulation::vx() const { return system_->particles().vx.data(); }
const double* Simulation::vy() const { return system_->particles().vy.data(); }
const double* Simulation::omega() const { return system_->particles().omega.data(); }
const double* Simulation::diameter() const { return system_->particles().diameter.data(); }
const double* Simulation::mass() const { return system_->particles().mass.data(); }
const int* Simulation::classIndex() const { return system_->particles().classIndex.data(); }
const std::int64_t* Simulation::id() const { return system_->particles().id.data(); }

double* Simulation::dragCoefficient() { return system_->particles().dragCoefficient.data(); }
double* Simulation::gasVelocityX() { return system_->particles().gasVx.data(); }
double* Simulation::gasVelocityY() { return system_->particles().gasVy.data(); }
double* Simulation::extraForceX() { return system_->particles().extraFx.data(); }
double* Simulation::extraForceY() { return system_->particles().extraFy.data(); }

void Simulation::advance(double dtOuter) { system_->advance(dtOuter); }
void Simulation::sortByCell() { system_->sortByCell(); }

const double* Simulation::meanVelocityX() const { return system_->particles().meanVx.data(); }
const double* Simulation::meanVelocityY() const { return system_->particles().meanVy.data(); }
const double* Simulation::meanFluidForceX() const { return system_->particles().meanFluidX.data(); }
const double* Simulation::meanFluidForceY() const { return system_->particles().meanFluidY.data(); }

double Simulation::time() const { return system_->time(); }
std::int64_t Simulation::stepCount() const { return system_->stepCount(); }
double Simulation::kineticEnergy() const { return system_->kineticEnergy(); }
double Simulation::timeStepBound() const { return system_->timeStepBound(); }
std::size_t Simulation::contactCount() const { return system_->contactCount(); }
double Simulation::elasticEnergy() const { return system_->elasticEnergy(); }
double Simulation::maxOverlap() const { return system_->maxOverlap(); }
std::int64_t Simulation::neighbourListBuilds() const { return system_->neighbourListBuilds(); }
std::size_t Simulation::memoryBytes() const { return system_->memoryBytes(); }

void Simulation::save(const std::string& path) const { system_->save(path); }
void Simulation::load(const std::string& path) { system_->load(path); }
bool Simulation::loadBed(const std::string& path, const BedRecipe& recipe)
{
    return system_->loadBed(path, recipe);
}
const BedRecipe* Simulation::recipe() const { return system_->recipe(); }

} // namespace dem
