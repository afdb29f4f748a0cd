// `--method M [--forgetting λ]` of the commands that identify a campaign (identify, report):
// which of the papers' estimators runs (ident::Method) and the RLS forgetting factor (ref 004
// eq. 15).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "uuvplan/ident/identify.h"

namespace uuvplan::cli {

struct MethodFlags {
  std::string method{ident::MethodName(ident::IdentifyOptions{}.method)};
  bool forgetting_given = false;
  double forgetting = ident::RlsOptions{}.lambda;
};

/// Binds --method and --forgetting to `flags`.
void AddMethodOptions(CLI::App* sub, MethodFlags* flags);

/// Sets `o->method` and `o->rls.lambda`; model::InputError (exit 2) for an unknown method or
/// --forgetting with a method other than rls.
void ApplyMethodFlags(const MethodFlags& flags, ident::IdentifyOptions* o);

}  // namespace uuvplan::cli
