// --method and --forgetting (method_flags.h).
#include "uuvplan/cli/method_flags.h"

#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::cli {

void AddMethodOptions(CLI::App* sub, MethodFlags* flags) {
  sub->add_option("--method", flags->method,
                  "estimator: chain (the best chain: steady state + integral or one-step LS, "
                  "then output error), ls (steady-state LS, seed 000 eqs. 7-12; m a priori), "
                  "integral (+ m by seed 000 eqs. 16-19), one-step (seeds 002/004), rls "
                  "(seed 004 eq. 15), output-error (from the a priori values)")
      ->capture_default_str();
  sub->add_option_function<double>(
      "--forgetting",
      [flags](double lambda) {
        flags->forgetting = lambda;
        flags->forgetting_given = true;
      },
      "RLS forgetting factor λ in (0.9, 1] (--method rls; default " +
          model::Significant(ident::RlsOptions{}.lambda, 3) + ", memory ≈ 1/(1 − λ) rows)");
}

void ApplyMethodFlags(const MethodFlags& flags, ident::IdentifyOptions* o) {
  const auto method = ident::ParseMethod(flags.method);
  if (!method) {
    throw model::InputError("--method " + flags.method, "expected one of " + ident::MethodNames());
  }
  o->method = *method;
  if (flags.forgetting_given && o->method != ident::Method::kRls) {
    throw model::InputError("--forgetting",
                            "the forgetting factor belongs to --method rls (seed "
                            "004 eq. 15), not to method " +
                                flags.method);
  }
  o->rls.lambda = flags.forgetting;
}

}  // namespace uuvplan::cli
