#pragma once
// Short-range contact (Silling-Askari, Peridigm's "Short Range Force"): points of the contact
// lists closer than the contact radius repel each other, with optional Coulomb-type friction.
// The lists come from a search in the current configuration every `Search Frequency` steps and
// hold the points within the search radius that are not bonded. Each owned point sums its own
// list in global-id order (rank-count independent), taking both ends' share of each pair.
#include <memory>
#include <string>
#include <vector>

#include "contact/ContactConfig.hpp"
#include "core/Timers.hpp"
#include "discretization/PointCloud.hpp"
#include "parallel/Topology.hpp"

namespace peridot {

class ShortRangeContact {
 public:
  // `blockNameOfPoint`, `horizon`, `volume`: per owned point.
  ShortRangeContact(const ContactConfig& config, const Topology& topology,
                    const std::vector<std::string>& blockNameOfPoint, const double* horizon,
                    const double* volume, Timers& timers);

  // Rebuilds the contact lists from the current owned coordinates (collective). Each rank
  // searches its owned points among themselves and a halo: the other ranks' points within the
  // search radius of its box of current owned positions (one all-to-all; no rank sees the whole
  // cloud unless its box covers it).
  void search(const double* y);
  // Halo points this rank received at the last search (for tests and measurements).
  long long numHaloPoints() const { return numHaloPoints_; }
  // Contact lists of the owned points, as global ids in list order (for tests).
  std::vector<std::vector<long long>> contactListIds() const;
  // Contact force density of the owned points (collective: refreshes contact ghosts).
  void computeForce(const double* y, const double* v, double* contactForce);
  // The friction coefficient of the next evaluations (a time-dependent model's value at t).
  void setFrictionCoefficient(double mu) { config_.frictionCoefficient = mu; }

 private:
  void refresh(const double* owned, std::vector<double>& ghost);

  ContactConfig config_;
  const Topology& topology_;
  const double* horizon_;  // owned
  const double* volume_;   // owned
  Timers& timers_;
  std::vector<int> blockIndex_;          // owned, index into blockNames_
  std::vector<std::string> blockNames_;  // every rank's block names, sorted: same on all ranks
  long long numHaloPoints_ = 0;
  // Contact lists: neighbours are indices into [owned points | contact ghosts].
  std::vector<std::int64_t> offsets_;
  std::vector<int> neighbors_;
  std::vector<double> ghostVolume_, ghostHorizon_, ghostY_, ghostV_;
  Teuchos::RCP<const Map> ghostMap3_;
  Teuchos::RCP<const Import> ghostImport3_;
};

}  // namespace peridot
