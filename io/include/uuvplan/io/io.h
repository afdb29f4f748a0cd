// The io layer's readers and writers of the files a user writes (vehicle, pool, truth,
// campaign, trial logs), for callers that want them all. Results formats (schedule,
// identification, diagnosis JSON) have their own headers.
#pragma once

#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/files.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/trial_log_csv.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/input_error.h"
