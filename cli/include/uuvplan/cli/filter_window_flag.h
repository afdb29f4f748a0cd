// `--sg-window N` of every command that prepares a campaign's trials (identify, diagnose,
// score, report): the points of the Savitzky–Golay velocity filter (ident::TrialDataOptions;
// by default ref 000 §IV-D's 21–41 for the sampling rate). One flag for all of them, so that
// a campaign gets the same velocity estimate, and so the same answer, from every command.
#pragma once

#include <CLI/CLI.hpp>

#include "uuvplan/ident/prepare/trial_data.h"

namespace uuvplan::cli {

/// Binds --sg-window to `data->sg_window`.
void AddFilterWindowOption(CLI::App* sub, ident::TrialDataOptions* data);

/// model::InputError (exit 2) unless the window is the default or odd and at least order + 2
/// (TrialDataOptions::IsValid's rule; the only one of its fields a user sets).
void CheckFilterWindow(const ident::TrialDataOptions& data);

}  // namespace uuvplan::cli
