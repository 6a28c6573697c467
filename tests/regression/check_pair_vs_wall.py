#!/usr/bin/python3
"""Two identical bodies at the relative speed 2v against one body on the
wall at v (tests/regression/pair_identical_disks.prm): the same epsilon,
contact time and peak force (and plastic work, of E(0), where the bodies
yield), twice the approach, equal vibration energies, momentum and impulse
balances.

usage: check_pair_vs_wall.py PAIR_SUMMARY.csv WALL_SUMMARY.csv TOL
"""
import csv
import sys

pair_file, wall_file, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
pair = next(csv.DictReader(open(pair_file)))
wall = next(csv.DictReader(open(wall_file)))
failures = []


def close(name, a, b, tolerance):
    error = abs(a - b) / max(abs(a), abs(b))
    status = "ok" if error <= tolerance else "FAIL"
    print(f"{status}: {name} {a:.15g} against {b:.15g} (relative {error:.2e})")
    if error > tolerance:
        failures.append(name)


close("relative speed / 2", float(pair["velocity"]) / 2, float(wall["velocity"]), 1e-15)
for name in ["epsilon", "contact_time", "force_max", "time_step"]:
    close(name, float(pair[name]), float(wall[name]), tol)
close("delta_max / 2", float(pair["delta_max"]) / 2, float(wall["delta_max"]), tol)
if float(wall.get("plastic_work") or "nan") > 0:
    # Elastic-plastic bodies: each yields as the body on the wall.
    close("plastic_work", float(pair["plastic_work"]), float(wall["plastic_work"]), tol)


def close_absolute(name, a, b, tolerance):
    # Vibration energies are differences of O(E0) energies: an absolute
    # tolerance in units of E0.
    error = abs(a - b)
    status = "ok" if error <= tolerance else "FAIL"
    print(f"{status}: {name} {a:.15g} against {b:.15g} (difference {error:.2e} E0)")
    if error > tolerance:
        failures.append(name)


close_absolute("partner's vibration energy", float(pair["partner_vibration_fraction"]),
               float(pair["vibration_fraction"]), 1e-10)
close_absolute("both vibration energies", 2 * float(pair["vibration_fraction"]),
               float(wall["vibration_fraction"]), 1e-10)
for name, limit in [("momentum_error", 1e-10), ("impulse_error", 1e-10),
                    ("energy_error", 1e-6)]:
    value = float(pair[name])
    status = "ok" if value <= limit else "FAIL"
    print(f"{status}: {name} {value:.3e} <= {limit:g}")
    if value > limit:
        failures.append(name)
sys.exit("FAIL: " + ", ".join(failures) if failures else 0)
