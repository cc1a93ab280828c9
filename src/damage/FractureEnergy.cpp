#include "damage/FractureEnergy.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace peridot {

namespace {
const double kPi = 3.14159265358979323846;

const char* modeName(PlaneMode mode) {
  return mode == PlaneMode::PlaneStress   ? "plane stress"
         : mode == PlaneMode::PlaneStrain ? "plane strain"
                                          : "3D";
}
}  // namespace

double criticalStretchFromFractureEnergy(const MaterialModel& material, double horizon, double G0,
                                         const std::string& w, std::string& formulaUsed,
                                         const std::string& path) {
  const std::string family = material.family();
  const PlaneMode mode = material.planeMode();
  const bool planar = mode != PlaneMode::ThreeD;
  const double delta = horizon;
  if (!(delta > 0)) throw InputError(path, "needs a constant horizon");
  // J_k = integral_0^delta omega zeta^k dzeta (closed forms in influenceIntegral).
  auto J = [&](int k) {
    double v = 0;
    if (!influenceIntegral(w, k, delta, v)) {
      throw InputError(path, "no fracture-energy formula for the influence function \"" + w +
                                 "\" (One, Conical and Conical Over Zeta have one); give "
                                 "Critical Stretch");
    }
    return v;
  };
  const std::string where = std::string(" (") + modeName(mode) + ", omega " + w + ")";
  if (family == "bond-based") {
    const double K = material.bulkModulus();
    if (!planar) {
      if (w == "One") {
        // Silling and Askari (2005): G0 = pi c s_c^2 delta^5 / 10, c = 18 K / (pi delta^4).
        formulaUsed = "3D PMB, sqrt(5 G0 / (9 K delta))";
        return std::sqrt(5.0 * G0 / (9.0 * K * delta));
      }
      // c = 9 K / (2 pi J3), G0 = pi c s^2 J4 / 2.
      formulaUsed = "PMB, sqrt(4 G0 J3 / (9 K J4))" + where;
      return std::sqrt(4.0 * G0 * J(3) / (9.0 * K * J(4)));
    }
    // c = 4 kappa / (pi t J2), G0 = c s^2 t J3; conical plane stress: sqrt(5 pi G0 / (9 E delta))
    // (paper 001 eq. 22), omega = 1 plane stress: sqrt(4 pi G0 / (9 E delta)).
    const double kappa =
        inPlaneBulkModulus(material.youngsModulus(), material.poissonsRatio(), mode);
    formulaUsed = "PMB, sqrt(pi G0 J2 / (4 kappa J3)), kappa = " + std::to_string(kappa) + where;
    return std::sqrt(kPi * G0 * J(2) / (4.0 * kappa * J(3)));
  }
  if (family == "normalized PMB") {
    if (!planar) {
      // Bulk c = 18 K / (4 pi J2), G0 = pi c s^2 J3 / 2.
      formulaUsed = "normalized PMB, sqrt(4 G0 J2 / (9 K J3))" + where;
      return std::sqrt(4.0 * G0 * J(2) / (9.0 * material.bulkModulus() * J(3)));
    }
    // Bulk c = 8 kappa / (2 pi t J1), G0 = c s^2 t J2 (paper 000 eq. 21 counts each bond twice:
    // see doc/theory/planar-and-fracture-energy.md). omega = 1: sqrt(3 pi G0 / (8 kappa delta)).
    const double kappa =
        inPlaneBulkModulus(material.youngsModulus(), material.poissonsRatio(), mode);
    formulaUsed =
        "normalized PMB, sqrt(pi G0 J1 / (4 kappa J2)), kappa = " + std::to_string(kappa) + where;
    return std::sqrt(kPi * G0 * J(1) / (4.0 * kappa * J(2)));
  }
  // The linearized LPS (LSJ-T) has the LPS bond term alpha/2 sum omega zeta^2 eps^2 V.
  if (family == "LPS" || family == "linearized LPS") {
    const double E = material.youngsModulus(), nu = material.poissonsRatio();
    const double mu = E / (2.0 * (1.0 + nu));
    if (!planar) {
      // alpha = 15 mu / m, m = 4 pi J4; G0 = pi alpha s^2 J5 (bond term only).
      formulaUsed = "LPS bond term, sqrt(4 G0 J4 / (15 mu J5))" + where;
      return std::sqrt(4.0 * G0 * J(4) / (15.0 * mu * J(5)));
    }
    // alpha = 8 mu / m, m = 2 pi t J3; G0 = 2 alpha s^2 t J4 (bond term only). Conical Over Zeta
    // (paper 001's omega): sqrt(5 (1 + nu) pi G0 / (12 E delta)), its eq. (24).
    formulaUsed = "LPS bond term, sqrt(pi G0 J3 / (8 mu J4))" + where;
    return std::sqrt(kPi * G0 * J(3) / (8.0 * mu * J(4)));
  }
  if (family == "continuum kinematics") {
    // Paper 004 eq. (3.3) (Madenci and Oterkus), with G the shear modulus and K the bulk
    // modulus (3D) or the in-plane bulk modulus of the plane mode (2D); omega = 1 only.
    if (w != "One") {
      throw InputError(path,
                       "the continuum-kinematics fracture-energy formula (paper 004 eq. "
                       "3.3) assumes the influence function \"One\"");
    }
    const double E = material.youngsModulus(), nu = material.poissonsRatio();
    const double G = E / (2.0 * (1.0 + nu));
    if (!planar) {
      const double K = material.bulkModulus();
      formulaUsed = "CKI 3D, sqrt(G0 / (delta (3G + (3/4)^4 (K - 5G/3))))";
      return std::sqrt(G0 / (delta * (3.0 * G + std::pow(0.75, 4) * (K - 5.0 * G / 3.0))));
    }
    const double K = inPlaneBulkModulus(E, nu, mode);
    formulaUsed =
        "CKI 2D, sqrt(G0 / (delta (6G/pi + 16/(9 pi^2) (K - 2G)))), K = " + std::to_string(K) +
        where;
    return std::sqrt(G0 / (delta * (6.0 / kPi * G + 16.0 / (9.0 * kPi * kPi) * (K - 2.0 * G))));
  }
  throw InputError(
      path, "no fracture-energy formula for a " + family + " material; give Critical Stretch");
}

CriticalStretchInput::CriticalStretchInput(ListReader& p) : path_(p.path()) {
  if (p.has("Critical Stretch") == p.has("Fracture Energy")) {
    throw InputError(p.path(), "give exactly one of \"Critical Stretch\" and \"Fracture Energy\"");
  }
  if (p.has("Critical Stretch")) {
    criticalStretch_ = p.positiveNumber("Critical Stretch");
  } else {
    fractureEnergy_ = p.positiveNumber("Fracture Energy");
  }
}

void CriticalStretchInput::bind(const MaterialModel& material, double horizon,
                                const std::string& blockName, std::ostream& log) {
  if (fractureEnergy_ <= 0) return;
  if (!(horizon > 0)) {
    throw InputError(path_ + " -> Fracture Energy",
                     "needs a constant horizon in block " + blockName);
  }
  std::string formula;
  criticalStretch_ = criticalStretchFromFractureEnergy(
      material, horizon, fractureEnergy_, material.influenceFunctionAssumed(), formula,
      path_ + " -> Fracture Energy (block " + blockName + ")");
  log << "Critical stretch of block " << blockName << " from the fracture energy "
      << fractureEnergy_ << ": " << criticalStretch_ << " (" << formula << ")\n";
}

}  // namespace peridot
