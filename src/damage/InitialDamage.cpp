#include "damage/InitialDamage.hpp"

#include "core/Error.hpp"

namespace peridot {

InitialDamage::InitialDamage(ListReader& p) {
  ListReader filters = p.sublist("Bond Filters");
  for (const auto& name : filters.keys())
    filters_.push_back(readBondFilter(filters.sublist(name), name));
  filters.finish();
  if (filters_.empty()) throw InputError(filters.path(), "no bond filter is defined");
  p.boolean("Verbose", false);
}

void InitialDamage::initializeDamage(const ModelState& s, const std::vector<int>& points,
                                     float* bondDamage) {
  const std::int64_t* offsets = s.topology->bondOffsets.data();
  const int* neighbors = s.topology->neighbors.data();
  const long long* gid = s.topology->overlapGlobalId.data();
  for (int i : points) {
    for (std::int64_t b = offsets[i]; b < offsets[i + 1]; ++b) {
      const int j = neighbors[b];
      // The segment always from the end with the smaller id: both entries of a bond, on any
      // rank, ask the same question with the same operands, so they agree to the bit.
      const double* p = gid[i] < gid[j] ? &s.x[3 * i] : &s.x[3 * j];
      const double* q = gid[i] < gid[j] ? &s.x[3 * j] : &s.x[3 * i];
      for (const auto& f : filters_)
        if (f.cuts(p, q)) {
          bondDamage[b] = 1.0f;
          break;
        }
    }
  }
}

PERIDOT_REGISTER_DAMAGE(
    "Initial Damage", InitialDamage,
    "Bonds crossing the bond filters start broken (kept in the lists, counted in Damage); no "
    "further breaking",
    (std::vector<ParameterDoc>{
        {"Bond Filters",
         "list, required: one sublist per filter, Type Rectangular_Plane (Normal_X/Y/Z, "
         "Lower_Left_Corner_X/Y/Z, Bottom_Unit_Vector_X/Y/Z, Bottom_Length, Side_Length), "
         "Exodus Mesh (File Name of a TRI3/QUAD4/SHELL4 shell mesh) or Disk (Center_X/Y/Z, "
         "Normal_X/Y/Z, Radius; a Peridot extension here)"},
        {"Verbose", "bool, default false"}}))

}  // namespace peridot
