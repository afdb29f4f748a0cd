// --sg-window (filter_window_flag.h).
#include "uuvplan/cli/filter_window_flag.h"

#include <string>

#include "uuvplan/model/input_error.h"

namespace uuvplan::cli {

void AddFilterWindowOption(CLI::App* sub, ident::TrialDataOptions* data) {
  sub->add_option("--sg-window", data->sg_window,
                  "points of the Savitzky-Golay velocity filter, odd (default: the seeds' "
                  "21-41 for the sampling rate, fewer for fast inputs; a precise sensor on fast "
                  "transients wants fewer, docs/identification.md)");
}

void CheckFilterWindow(const ident::TrialDataOptions& data) {
  if (!data.IsValid(nullptr)) {
    throw model::InputError("--sg-window " + std::to_string(data.sg_window),
                            "expected an odd number of points, at least " +
                                std::to_string(data.sg_order + 3 - data.sg_order % 2) +
                                " (the filter fits a polynomial of order " +
                                std::to_string(data.sg_order) + ")");
  }
}

}  // namespace uuvplan::cli
