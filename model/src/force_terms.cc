// Factories of the force terms; the terms themselves are in force_terms_impl.h.
#include "force_terms_impl.h"

namespace uuvplan::model {

using namespace internal;

std::unique_ptr<ForceTerm> MakeDragTerm(bool linear, bool quadratic, bool asymmetric) {
  return std::make_unique<DragTerm>(linear, quadratic, asymmetric);
}

std::unique_ptr<ForceTerm> MakeThrustTerm(const std::vector<std::string>& mapping_names,
                                          const std::vector<std::string>& free_eta) {
  return MakeThrust(mapping_names, free_eta);
}

std::unique_ptr<ForceTerm> MakeConstantTerm(bool bias, bool ballast) {
  return std::make_unique<ConstantTerm>(bias, ballast);
}
std::unique_ptr<ForceTerm> MakeAdvanceLossTerm() { return std::make_unique<AdvanceLossTerm>(); }
std::unique_ptr<ForceTerm> MakeCouplingTerm(Dof own, const std::vector<std::string>& pairs) {
  return std::make_unique<CouplingTerm>(own, pairs);
}
std::unique_ptr<ForceTerm> MakeDriftTerm() { return std::make_unique<DriftTerm>(); }

}  // namespace uuvplan::model
