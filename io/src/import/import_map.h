// The map of `uuvplan import`: how a lab's recordings become trials (docs/import.md). It names
// the topic and field of each thruster's command with its unit, how a command becomes force
// (a thrust table and the arms of each DOF, or cmd_ columns for the vehicle's own thrust
// model), each measured signal with its scale, offset and axis convention, the clocks of
// devices that stamp their own samples, and how trials are cut.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "uuvplan/model/campaign.h"
#include "uuvplan/model/dof.h"

namespace uuvplan::io::import {

enum class CommandUnit { kPwmMicroseconds, kNormalised, kNewton };
enum class Cut { kFile, kActivity, kRanges };

struct MeasuredSignal {
  std::string column;  ///< pos_<dof> or vel_<dof>
  model::Dof dof = model::Dof::kSurge;
  bool position = false;
  std::string topic;
  std::string field;
  double scale = 1.0;  ///< logged value × scale + offset, before the axis convention
  double offset = 0.0;
  double sign = 1.0;  ///< +1, or -1 where ENU/FLU and NED/FRD disagree on the axis
  double turn = 0.0;  ///< rad added after the sign (ENU heading: π/2 − ψ)
  std::string frame;  ///< as written: ned, enu, frd or flu
};

/// A device that stamps its own samples (a microcontroller's millis()): `field` × `scale` is
/// its time in s, mapped onto the recorder clock unless `align` is false.
struct DeviceClock {
  std::string field;
  double scale = 1.0;
  bool align = true;
};

struct ImportMap {
  std::string file;
  std::string files;  ///< glob of recordings in the source directory ("" = *.bag, *.mcap)
  /// `rostopic echo -p` exports: topic → CSV file name in each run's directory (empty: bags)
  std::map<std::string, std::string> csv_topics;
  std::string trial_id;  ///< regex whose first group names a file's trial ("" = the stem)
  std::string vehicle;   ///< path, resolved against the source directory
  model::Dof dof = model::Dof::kSurge;
  std::string mapping;
  std::map<std::string, model::TrialUse> use;  ///< by trial id; others are fit

  std::string command_topic;
  CommandUnit unit = CommandUnit::kNormalised;
  double neutral = 1500.0;    ///< µs of PWM at zero command
  double full_scale = 400.0;  ///< µs of PWM from neutral to a command of ±1
  std::vector<std::pair<std::string, std::string>> thrusters;  ///< name, field
  std::string thrust_table_file;                               ///< as written ("" = none)
  std::vector<std::array<double, 2>> thrust_table;             ///< (command, N), command ascending
  std::map<model::Dof, std::map<std::string, double>> forces;  ///< arms (m, or 1 for forces)

  std::vector<MeasuredSignal> measured;
  std::map<std::string, DeviceClock> clocks;  ///< by topic
  Cut cut = Cut::kFile;
  double quiet_s = 2.0;  ///< activity cut: a pause this long with every command at zero
  /// ranges cut: per recording's trial id, [start, end] in s after its first command message
  std::map<std::string, std::vector<std::array<double, 2>>> ranges;

  /// The normalised command (or N) of a logged value.
  double Command(double logged) const {
    return unit == CommandUnit::kPwmMicroseconds ? (logged - neutral) / full_scale : logged;
  }
  /// Thrust (N) of one thruster at a command: the table, linearly interpolated (N as logged).
  double Thrust(double command) const;
  bool WritesForces() const { return !forces.empty(); }
};

/// Reads the map; paths in it (vehicle, thrust table) are relative to `source_dir`; the
/// vehicle is left out unless `read_vehicle` (another file was given). Every fault names the
/// map file, line and key.
ImportMap ReadImportMap(const std::string& file, const std::string& source_dir, bool read_vehicle);

}  // namespace uuvplan::io::import
