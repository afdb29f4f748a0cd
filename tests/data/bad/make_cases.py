#!/usr/bin/env python3
"""Writes the malformed-input suite: tests/data/bad/cases/<format>_<case>.<ext>,
mutations of the valid files of tests/data/io, and cases/expectations.tsv, which
tests/cli/malformed_input_test.cc runs: every case must exit with status 2 and name its file
and line or key. Regenerate after changing a case: python3 tests/data/bad/make_cases.py

expectations.tsv columns (tab-separated): case, uuvplan arguments ({cases}: this directory,
{data}: tests/data, {out}: a new directory), the texts the message must contain (" && "
between them), the texts it must not contain (a file of the wrong format is not echoed).
"""
import json
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.dirname(HERE)
OUT = os.path.join(HERE, "cases")
IO = os.path.join(DATA, "io")

rows = []


def read(name):
    with open(os.path.join(IO, name), encoding="utf-8") as f:
        return f.read()


def write(name, text, mode="w"):
    with open(os.path.join(OUT, name), mode) as f:
        f.write(text)


def mutate(text, pattern, replacement):
    """Replaces the first line matching `pattern`; returns (text, 1-based line of it)."""
    lines = text.split("\n")
    for i, line in enumerate(lines):
        if re.search(pattern, line):
            lines[i] = re.sub(pattern, replacement, line, count=1)
            return "\n".join(lines), i + 1
    raise ValueError("no line matches " + pattern)


def case(name, args, needles, forbidden=""):
    rows.append((name, args, " && ".join(needles), forbidden))


def mutated_case(file, base, pattern, replacement, command, key_message, line_shift=0):
    """A mutation of `base` written to `file`, run by `command % file`; the message names the
    mutated line (+ line_shift: a list item is reported at its first line)."""
    text, line = mutate(base, pattern, replacement)
    write(file, text)
    case(file, command % file, ["%s:%d: %s" % (file, line + line_shift, key_message)])


# --- vehicle files: `schedule VEHICLE --pool POOL` -------------------------------------------
VEHICLE = read("vehicle.yaml")
SCHEDULE = "schedule {cases}/%s --pool {data}/io/pool.yaml"


def vehicle_case(name, pattern, replacement, key_message, line_shift=0):
    mutated_case("vehicle_%s.yaml" % name, VEHICLE, pattern, replacement, SCHEDULE, key_message,
                 line_shift)


vehicle_case("mass_tiny", r"^mass: .*", "mass: 1e-300", "mass: implausible: expected a vehicle mass")
vehicle_case("mass_huge", r"^mass: .*", "mass: 1e308", "mass: implausible")
vehicle_case("mass_negative", r"^mass: .*", "mass: -5", "mass: expected a positive number")
vehicle_case("mass_text", r"^mass: .*", "mass: heavy", "mass: expected a positive number, got 'heavy'")
vehicle_case("mass_nan", r"^mass: .*", "mass: .nan", "mass: expected a positive number")
vehicle_case("size_two", r"^size: .*", "size: [1.3, 0.9]", "size: expected [length, width, height]")
vehicle_case("size_huge", r"^size: .*", "size: [1e6, 0.9, 1.0]", "size[0]: implausible")
vehicle_case("inertia_tiny", r"^inertia: .*", "inertia: {yaw: 1e-9}", "inertia.yaw: implausible")
vehicle_case("inertia_surge", r"^inertia: .*", "inertia: {surge: 5}", "inertia: inertia is given")
vehicle_case("thrust_huge", r"c_pos: 1.02", "c_pos: 1e308", "thrusters[0]: implausible",
             line_shift=-1)
vehicle_case("command_reversed", r"command: \[-10, 10\]", "command: [10, -10]",
             "thrusters[0].command: expected a command range")
vehicle_case("command_pwm_no_neutral", r"command: \[-10, 10\]", "command: [1100, 1900]",
             "thrusters[0].command: the command range [1100, 1900] does not hold 0")
vehicle_case("neutral_outside", r"command: \[-10, 10\]", "command: [-10, 10]\n    neutral: 12",
             "thrusters[0].neutral: expected the command at which the thruster stops",
             line_shift=1)
vehicle_case("unknown_key", r"^min_thrust: .*", "colour: red", "unknown key 'colour'")
vehicle_case("duplicate_key", r"^min_thrust: .*", "mass: 450", "key 'mass' appears twice")
vehicle_case("share_unknown", r"shares: \{HFL: 0.5, HFR: 0.5\}", "shares: {HFL: 0.5, HXX: 0.5}",
             "mappings.surge-front.shares: unknown thruster 'HXX'")
vehicle_case("share_zero", r"shares: \{HFL: 0.5, HFR: 0.5\}", "shares: {HFL: 0.5, HFR: 0}",
             "mappings.surge-front.shares.HFR: expected a non-zero share")
vehicle_case("sensor_rate_huge", r"surge: \{position: \{rate: 3.33",
             "surge: {position: {rate: 1e9", "sensors.surge.position.rate: implausible")
vehicle_case("sensor_sigma_huge", r"sigma: 0.02\}", "sigma: 1e6}",
             "sensors.surge.position.sigma: implausible")
vehicle_case("sensor_rate_zero", r"surge: \{position: \{rate: 3.33",
             "surge: {position: {rate: 0", "sensors.surge.position.rate: expected a positive")
vehicle_case("dof_unknown", r"^  surge:$", "  surgee:", "dofs: expected a DOF")
vehicle_case("drag_negative", r"drag: \{k: 46.9", "drag: {k: -1", "dofs.surge.drag.k: expected a number >= 0")
vehicle_case("drag_kq_huge", r"drag: \{k: 46.9, kq: 306.2", "drag: {k: 46.9, kq: 1e308",
             "dofs.surge.drag.kq: implausible: expected |kq|")
vehicle_case("added_mass_reversed", r"^added_mass: .*", "added_mass: [1.0, 0.1]",
             "added_mass: expected [lo, hi]")
vehicle_case("not_yaml", r"^mass: .*", "mass: [450", "not valid YAML", line_shift=1)

name = "vehicle_missing_name.yaml"
write(name, re.sub(r"(?m)^name: .*\n", "", VEHICLE))
case(name, SCHEDULE % name, [name + ": missing required key 'name'"])
name = "vehicle_nul.yaml"
text, line = mutate(VEHICLE, r"^mass: .*", "mass: 45\0" + "0")
write(name, text)
case(name, SCHEDULE % name, ["%s:%d: a NUL byte" % (name, line)])
name = "vehicle_deep.yaml"
write(name, "name: x\nmass: " + "[" * 100000 + "\n")
case(name, SCHEDULE % name, [name + ":2: brackets [ ] or { } nested more than 64"])
name = "vehicle_passwd.yaml"
write(name, "root:x:0:0:root:/root:/bin/bash\ndaemon:x:1:1:daemon:/usr/sbin:/usr/sbin/nologin\n")
case(name, SCHEDULE % name, [name + ": expected a map of vehicle keys"], "root:x")
name = "vehicle_empty.yaml"
write(name, "# nothing\n")
case(name, SCHEDULE % name, [name + ": empty file"])
name = "vehicle_control.yaml"
write(name, "name: x\n\x01\x02\x03\n")
case(name, SCHEDULE % name, [name + ":2: the control byte 0x01"])

# --- pool files: `schedule VEHICLE --pool POOL` ----------------------------------------------
POOL = read("pool.yaml")


def pool_case(name, pattern, replacement, key_message):
    mutated_case("pool_%s.yaml" % name, POOL, pattern, replacement,
                 "schedule {data}/io/vehicle.yaml --pool {cases}/%s", key_message)


pool_case("length_huge", r"^length: \S+", "length: 1e308", "length: implausible: expected a pool dimension")
pool_case("width_zero", r"^width: \S+", "width: 0", "width: expected a positive number")
pool_case("depth_text", r"^depth: \S+", "depth: deep", "depth: expected a positive number, got 'deep'")
pool_case("depth_tiny", r"^depth: \S+", "depth: 1e-9", "depth: implausible")
pool_case("margin_too_big", r"^margin: \S+", "margin: 10", "margin: expected a margin that leaves room")
pool_case("unknown_key", r"^name: .*", "colour: blue", "unknown key 'colour'")
pool_case("max_turns_negative", r"^name: .*", "max_turns: -2", "max_turns: expected a positive number")
name = "pool_list.yaml"
write(name, "- 25\n- 12\n- 4\n")
case(name, "schedule {data}/io/vehicle.yaml --pool {cases}/" + name,
     [name + ": expected a map of pool keys, got a list"])

# --- truth files: `simulate --truth TRUTH --plan PLAN --out DIR` -----------------------------
TRUTH = read("truth.yaml")
PLAN = {"trials": [{"id": "s1", "dof": "surge", "kind": "steady", "duration": 10,
                    "mapping": "surge-front", "force": 50}]}
write("plan_good.json", json.dumps(PLAN) + "\n")
SIMULATE = "simulate --truth {cases}/%s --plan {cases}/plan_good.json --out {out}"


def truth_case(name, pattern, replacement, key_message):
    mutated_case("truth_%s.yaml" % name, TRUTH, pattern, replacement, SIMULATE, key_message)


truth_case("m_tiny", r"m: 890", "m: 1e-300", "dofs.surge.params.m: implausible: expected |m|")
truth_case("kq_huge", r"kq: 306.2, bias", "kq: 1e308, bias", "dofs.surge.params.kq: implausible")
truth_case("bias_huge", r"bias: 1.5", "bias: 1e12", "dofs.surge.params.bias: implausible")
truth_case("k_negative", r"k: 46.9, kq: 306.2, bias", "k: -4, kq: 306.2, bias",
           "dofs.surge.params.k: expected a number >= 0")
truth_case("step_tiny", r"step: 0.005", "step: 1e-9", "virtual_pool.step: implausible")
truth_case("step_zero", r"step: 0.005", "step: 0", "virtual_pool.step: expected a positive number")
truth_case("dropout_one", r"dropout_probability: 0.05", "dropout_probability: 1",
           "virtual_pool.dropout_probability: expected a probability in [0, 1)")
truth_case("effect_unknown", r"thruster_lag: \{lag: 0.3\}", "fancy_drag: {c: 1}",
           "dofs.surge.effects: expected an effect")
truth_case("lag_negative", r"lag: 0.3", "lag: -0.3", "dofs.surge.effects.thruster_lag.lag")
truth_case("eta_bad_mapping", r"eta: \{surge-front.neg: 0.8\}", "eta: {nomap.neg: 0.8}",
           "dofs.surge.params.eta")
truth_case("unknown_key", r"^virtual_pool: .*", "virtual_pool: {stepp: 0.01}",
           "virtual_pool: unknown key 'stepp'")
name = "truth_no_params.yaml"
write(name, re.sub(r"(?ms)^dofs:.*?(?=^virtual_pool)", "dofs:\n  sway:\n    drag: {k: 60, kq: 400}\n",
                  TRUTH))
case(name, SIMULATE % name, [name + ": expected dofs.<dof>.params for at least one DOF"])

# --- plans (JSON): `check-pool --plan PLAN VEHICLE --pool POOL` ------------------------------
CHECK = "check-pool --plan {cases}/%s {data}/io/vehicle.yaml --pool {data}/io/pool.yaml"


def plan_case(name, change, key_message, command=CHECK):
    plan = json.loads(json.dumps(PLAN))
    change(plan["trials"][0], plan)
    file = "plan_%s.json" % name
    write(file, json.dumps(plan) + "\n")
    case(file, command % file, ["%s: %s" % (file, key_message)])


plan_case("duration_huge", lambda t, p: t.update(duration=1e308),
          "trials[0].duration: implausible: expected a duration")
plan_case("duration_huge_simulate", lambda t, p: t.update(duration=1e308),
          "trials[0].duration: implausible",
          command="simulate --truth {data}/io/truth.yaml --plan {cases}/%s --out {out}")
plan_case("duration_negative", lambda t, p: t.update(duration=-3),
          "trials[0].duration: expected a positive number")
plan_case("duration_ms", lambda t, p: t.update(duration=1e7), "trials[0].duration: implausible")
plan_case("kind_unknown", lambda t, p: t.update(kind="wobble"), "trials[0].kind: expected a trial kind")
plan_case("dof_unknown", lambda t, p: t.update(dof="surf"), "trials[0].dof")
plan_case("id_missing", lambda t, p: t.pop("id"), "trials[0]: missing required key 'id'")
plan_case("force_text", lambda t, p: t.update(force="big"), "trials[0].force")
plan_case("ids_twice", lambda t, p: p["trials"].append(dict(t)), "trials[1].id")
plan_case("segments_sum", lambda t, p: t.update(
    kind="segments", segments=[{"force": 10, "duration": 4}, {"force": -10, "duration": 4}]),
    "trials[0].duration: expected the segments' durations to add up")
name = "plan_number_overflow.json"  # found by fuzz_plan: exit 3 before
write(name, json.dumps(PLAN).replace('"duration": 10', '"duration": 2e+308') + "\n")
case(name, CHECK % name, [name + ": not valid JSON: number overflow parsing '2e+308'"])
name = "plan_not_json.json"
write(name, "trials: [\n")
case(name, CHECK % name, [name + ":1:3: not valid JSON"])
name = "plan_deep.json"
write(name, "[" * 100000)
case(name, CHECK % name, [name + ":1: brackets [ ] or { } nested more than 64"])
name = "plan_passwd.json"
write(name, "rootpassword:x:0:0:root:/root:/bin/bash\n")
case(name, CHECK % name, [name + ":1:1: not valid JSON"], "rootpassword")
name = "plan_list.json"
write(name, "[1, 2]\n")
case(name, CHECK % name, [name + ": expected a schedule"])

# --- campaigns: `identify CAMPAIGN` ----------------------------------------------------------
CAMPAIGN = ("vehicle: ../../io/vehicle.yaml\npool: ../../io/pool.yaml\ntrials:\n"
            "  - file: ../../io/trials/surge_0.csv\n    dof: surge\n    use: fit\n    start: 0\n"
            "  - file: ../../io/trials/yaw_0.csv\n    dof: yaw\n    mapping: yaw-diff\n"
            "    use: validate\n    start: 100\n")


def campaign_case(name, pattern, replacement, key_message):
    mutated_case("campaign_%s.yaml" % name, CAMPAIGN, pattern, replacement, "identify {cases}/%s",
                 key_message)


name = "campaign_same_log_twice.yaml"
text, line = mutate(CAMPAIGN.replace("dof: yaw", "dof: surge").replace("mapping: yaw-diff", "mapping: surge-front"),
                    r"yaw_0.csv", "surge_0.csv")
write(name, text)
case(name, "identify {cases}/" + name,
     ["%s:%d: trials[1].file: implausible: the same log as trials[0]" % (name, line)])
campaign_case("dof_unknown", r"dof: yaw", "dof: yawn", "trials[1].dof: expected a DOF")
campaign_case("file_missing", r"yaw_0.csv", "nothere.csv", "trials[1].file: cannot open")
campaign_case("mapping_wrong_dof", r"mapping: yaw-diff", "mapping: surge-front", "trials[1].mapping")
campaign_case("start_decreasing", r"start: 100", "start: -5", "trials[1].start: expected a start >=")
campaign_case("use_unknown", r"use: validate", "use: test", "trials[1].use: expected a use")
campaign_case("ballast_negative", r"use: validate", "ballast_steps: -1",
              "trials[1].ballast_steps: expected a whole number >= 0")
campaign_case("vehicle_missing", r"^vehicle: .*", "vehicle: nothere.yaml", "vehicle: cannot open")
campaign_case("unknown_key", r"^pool: .*", "pools: x.yaml", "unknown key 'pools'")
name = "campaign_trials_map.yaml"
write(name, "vehicle: ../../io/vehicle.yaml\ntrials: {a: 1}\n")
case(name, "identify {cases}/" + name, [name + ":2: trials: expected a list of trials"])

# --- trial logs (CSV), each read through a one-trial campaign of the same name ---------------
CSV_ROWS = ["t,force_surge,pos_surge"] + [
    "%g,100,%g" % (0.3 * i, 0.01 * i * i) for i in range(30)]


def csv_case(name, lines, key_message, forbidden="", binary=False):
    file = "csv_%s.csv" % name
    text = "\n".join(lines) + "\n"
    if binary:
        write(file, text.encode("latin-1"), "wb")
    else:
        write(file, text)
    campaign = "csv_%s.yaml" % name
    write(campaign, "vehicle: ../../io/vehicle.yaml\ntrials:\n  - file: %s\n    dof: surge\n"
          "    mapping: surge-front\n" % file)
    case(file, "identify {cases}/" + campaign, ["%s%s" % (file, key_message)], forbidden)


def with_row(row_index, row):
    lines = list(CSV_ROWS)
    lines[row_index] = row
    return lines


csv_case("force_1e308", with_row(5, "1.2,1e308,0.16"),
         ": column 'force_surge' at t = 1.2 s (data row 5)")
csv_case("time_ms", [CSV_ROWS[0]] + [
    "%g,100,%g" % (300 * i, 0.01 * i * i) for i in range(30)], ": column 't' looks like milliseconds")
csv_case("rate_mismatch", [CSV_ROWS[0]] + [
    "%g,100,%g" % (3 * i, 0.01 * i * i) for i in range(30)], ": 'pos_surge' is sampled every 3 s")
csv_case("no_time", with_row(0, "time,force_surge,pos_surge"), ":1: header: expected a 't' column")
csv_case("passwd", ["root:x:0:0:root:/root:/bin/bash", "daemon:x:1:1:daemon"],
         ":1: header: expected a 't' column (time, s), got no known column", "root:x")
csv_case("time_decreasing", with_row(4, "0.1,100,0.09"), ":5: column 't': expected a time after")
csv_case("cell_text", with_row(3, "0.6,abc,0.04"), ":4: column 'force_surge': expected a number")
csv_case("cell_nan", with_row(3, "0.6,NaN,0.04"), ":4: column 'force_surge': expected a number")
csv_case("cell_inf", with_row(3, "0.6,inf,0.04"), ":4: column 'force_surge': expected a number")
csv_case("extra_cell", with_row(3, "0.6,100,0.04,7"), ":4: expected 3 cells as in the header, got 4")
csv_case("missing_cell", with_row(3, "0.6,100"), ":4: expected 3 cells as in the header, got 2")
csv_case("column_twice", with_row(0, "t,force_surge,force_surge"), ":1: header: column 'force_surge' appears twice")
csv_case("empty", ["# only a comment"], ": empty file")
csv_case("header_only", [CSV_ROWS[0]], ":1: no data rows after the header")
csv_case("time_empty", with_row(3, ",100,0.04"), ":4: column 't': expected a time (s), got an empty cell")
csv_case("no_force", with_row(0, "t,force_sway,pos_surge"), " has no 'force_surge' column")
csv_case("mapping_unknown", ["t,force_surge,pos_surge,mapping"] + [
    r + ",nomap" for r in CSV_ROWS[1:]], ":2: column 'mapping': expected a mapping of the vehicle")
csv_case("nul_cell", with_row(3, "0.6,1\x000,0.04"), ":4: column 'force_surge': expected a number",
         binary=True)

# --- recordings and import maps (uuvplan import) ---------------------------------------------
RECORDINGS = os.path.join(IO, "recordings")
IMPORT = "import {source} --map %s --out {out} --vehicle {data}/io/vehicle.yaml"
with open(os.path.join(RECORDINGS, "small_bz2.bag"), "rb") as f:
    BAG = f.read()
with open(os.path.join(RECORDINGS, "import.yaml"), encoding="utf-8") as f:
    IMPORT_MAP = f.read()


def recording_case(name, data, needles):
    write(name, data, "wb")
    case(name, (IMPORT % "{data}/io/recordings/import.yaml").replace(
        "{source}", "{cases}/" + name), needles)


def import_map_case(name, pattern, replacement, key_message):
    text, line = mutate(IMPORT_MAP, pattern, replacement)
    write(name, text)
    case(name, (IMPORT % ("{cases}/" + name)).replace("{source}", "{data}/io/recordings/small_bz2.bag"),
         # "!...": a message without a line (after the map was read whole)
         [name + key_message[1:] if key_message.startswith("!")
          else name + ":%d: %s" % (line, key_message)])


recording_case("recording_cut.bag", BAG[:len(BAG) // 2], ["recording_cut.bag: byte ", ": expected "])
recording_case("recording_text.bag", b"t,force_surge\n0,1\n", [
    "recording_text.bag: expected a ROS bag (format 2.0, '#ROSBAG V2.0') or an MCAP file, got "
    "a file starting 't,force_surge\\x0a0,'"])
recording_case("recording_chunk_size.bag", BAG.replace(b"size=", b"size=\xff", 1)[:len(BAG)], [
    "recording_chunk_size.bag: byte ", ": expected "])
recording_case("recording_mcap_cut.mcap", b"\x89MCAP0\r\n\x03\xff\xff\xff\x00", [
    "recording_mcap_cut.mcap: byte 9: expected a number of 8 bytes, got the end after 4"])
import_map_case("import_unit.yaml", r"unit: pwm_us", "unit: volts",
                "commands.unit: expected a unit (pwm_us, normalised, N), got 'volts'")
import_map_case("import_field.yaml", r"twist.linear.y", "twist.lineal.y",
                "!: measured: ")
import_map_case("import_key.yaml", r"^dof: yaw", "dofs: yaw", "unknown key 'dofs'")
import_map_case("import_thruster.yaml", r", VR: \"data\[3\]\"", "",
                "!: commands.thrusters: expected a field for every thruster")
import_map_case("import_frame.yaml", r"frame: flu", "frame: enu",
                "measured.vel_sway.frame: expected a body frame (frd, flu), got 'enu'")

# --- command-line values ---------------------------------------------------------------------
case("seed_negative", "simulate --truth {data}/io/truth.yaml --plan {cases}/plan_good.json "
     "--out {out} --seed -1", ["--seed: expected a whole number from 0 to 18446744073709551615, got -1"])
case("step_flag_negative", "simulate --truth {data}/io/truth.yaml --plan {cases}/plan_good.json "
     "--out {out} --step -0.01", ["--step"])

with open(os.path.join(OUT, "expectations.tsv"), "w", encoding="utf-8") as f:
    f.write("# Written by ../make_cases.py: case\targuments\tmust contain\tmust not contain\n")
    for row in rows:
        f.write("\t".join(row) + "\n")
print("%d cases in %s" % (len(rows), OUT))
