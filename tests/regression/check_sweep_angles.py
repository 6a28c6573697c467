#!/usr/bin/python3
"""A sweep's row at an angle of incidence against the single impact of the
same point: epsilon, the tangential and contact-point restitution and the
spin after, to TOL (relative).

usage: check_sweep_angles.py restitution.csv ANGLE summary.csv TOL
"""
import csv
import sys

table, angle, summary, tol = sys.argv[1], float(sys.argv[2]), sys.argv[3], \
    float(sys.argv[4])
with open(table, newline="") as f:
    rows = [r for r in csv.DictReader(f) if abs(float(r["angle"]) - angle) < 1e-9]
with open(summary, newline="") as f:
    single = next(csv.DictReader(f))
failed = len(rows) != 1 or rows[0]["status"] != "done"
if failed:
    print(f"no finished row at {angle} degrees")
    sys.exit(1)
for name in ("epsilon", "tangential_restitution", "contact_point_restitution",
             "spin_final"):
    a, b = float(rows[0][name]), float(single[name])
    d = abs(a / b - 1)
    ok = d <= tol
    failed |= not ok
    print(f"{name}: sweep {a:.12g}, single {b:.12g}: {d:.2e} "
          f"(bound {tol}) {'ok' if ok else 'FAIL'}")
sys.exit(1 if failed else 0)
