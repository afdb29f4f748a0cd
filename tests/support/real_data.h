// The real pool logs of ../shared/data (BlueROV yaw 2016, Tartan AUV 2022). They have no licence
// that lets the project ship them, so a clone of the repository alone lacks them: a test that
// reads them starts with UUVPLAN_SKIP_WITHOUT_REAL_DATA("<set>", ...) and is skipped there with
// a one-line reason, and runs unchanged where the data is present.
// Header-only: UUVPLAN_SHARED_DIR is a compile definition of the test programs.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>

namespace uuvplan::testing {

/// ../shared/data/<relative>, e.g. RealDataPath("bluerov-yaw-2016/campaign.yaml").
inline std::string RealDataPath(const std::string& relative) {
  return (std::filesystem::path(UUVPLAN_SHARED_DIR) / "data" / relative)
      .lexically_normal()
      .string();
}

/// Why the first absent data set of `sets` is missing, or "" when all are present.
inline std::string RealDataAbsence(std::initializer_list<const char*> sets) {
  for (const char* set : sets) {
    if (std::filesystem::is_directory(RealDataPath(set))) continue;
    return RealDataPath(set) +
           " not present: the real logs are not shipped with the project (no licence); see "
           "docs/diagnosis.md \"On real logs\"";
  }
  return "";
}

}  // namespace uuvplan::testing

/// In a test body: skips the test, with the reason, unless every named set of ../shared/data
/// is present.
#define UUVPLAN_SKIP_WITHOUT_REAL_DATA(...)                   \
  if (const std::string uuvplan_real_data_absence =           \
          ::uuvplan::testing::RealDataAbsence({__VA_ARGS__}); \
      uuvplan_real_data_absence.empty()) {                    \
  } else                                                      \
    GTEST_SKIP() << uuvplan_real_data_absence
