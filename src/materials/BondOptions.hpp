#pragma once
// The per-bond options a bond loop is instantiated for, so that its body has no branch on them
// and vectorizes: an influence array, bond damage, one-sided bonds (differing horizons).
#include "materials/MaterialModel.hpp"

namespace peridot {

template <bool kInfluence, bool kDamage, bool kSides>
struct BondOptions {
  static constexpr bool influence = kInfluence, damage = kDamage, sides = kSides;
};

// Calls loop(BondOptions<...>{}) with the options of the model state.
template <typename Loop>
void withBondOptions(const ModelState& s, Loop&& loop) {
  const int key =
      (s.influence ? 4 : 0) | (s.bondDamage || s.bondBroken ? 2 : 0) | (s.bondSides ? 1 : 0);
  switch (key) {
    case 0:
      return loop(BondOptions<false, false, false>{});
    case 1:
      return loop(BondOptions<false, false, true>{});
    case 2:
      return loop(BondOptions<false, true, false>{});
    case 3:
      return loop(BondOptions<false, true, true>{});
    case 4:
      return loop(BondOptions<true, false, false>{});
    case 5:
      return loop(BondOptions<true, false, true>{});
    case 6:
      return loop(BondOptions<true, true, false>{});
    default:
      return loop(BondOptions<true, true, true>{});
  }
}

}  // namespace peridot
