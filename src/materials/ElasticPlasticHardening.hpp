#pragma once
// Peridigm's "Elastic Plastic Hardening": the ordinary state-based plasticity of ElasticPlastic
// with linear isotropic hardening of the yield value, psi = psi_0 + H Lambda (H the deck's
// "Hardening Modulus", in units of psi per unit Lambda), the backward-Euler return mapping, and
// Peridigm's optional shear correction factor (alpha scaled by it, psi_0 by its square).
#include "materials/ElasticPlastic.hpp"

namespace peridot {

class ElasticPlasticHardening : public ElasticPlastic {
 public:
  explicit ElasticPlasticHardening(ListReader& params) : ElasticPlastic(params, true) {}
};

}  // namespace peridot
