#!/usr/bin/python3
"""A body in 3D against the two-dimensional model of the same impact (the
sphere's axisymmetric model, the plane-strain disk for a disk with held
faces): the two discretize the same problem, so their epsilon, contact time
and delta_max agree to the discretization error. epsilon within SHARE of the
2D model's loss 1 - epsilon, delta_max within RELATIVE, the contact time
within CONTACT_TIME (default RELATIVE).

usage: check_3d_vs_2d.py SOLID/summary.csv PLANE/summary.csv
                         --loss-share SHARE --relative RELATIVE
                         [--contact-time CONTACT_TIME]
"""
import argparse
import csv
import sys

p = argparse.ArgumentParser()
p.add_argument("solid")
p.add_argument("plane")
p.add_argument("--loss-share", type=float, required=True)
p.add_argument("--relative", type=float, required=True)
p.add_argument("--contact-time", type=float)
args = p.parse_args()


def summary(path):
    with open(path, newline="") as f:
        row = next(csv.DictReader(f))
    return {k: float(row[k]) for k in ("epsilon", "contact_time", "delta_max")}


solid, plane = summary(args.solid), summary(args.plane)
failed = False
loss = 1.0 - plane["epsilon"]
share = abs(solid["epsilon"] - plane["epsilon"]) / loss
ok = share <= args.loss_share
failed |= not ok
print(f"epsilon: 3D {solid['epsilon']:.8f}, 2D {plane['epsilon']:.8f}: "
      f"{share:.3g} of the loss {loss:.4g} (bound {args.loss_share}) "
      f"{'ok' if ok else 'FAIL'}")
bounds = {"contact_time": args.contact_time or args.relative,
          "delta_max": args.relative}
for name, bound in bounds.items():
    d = abs(solid[name] / plane[name] - 1.0)
    ok = d <= bound
    failed |= not ok
    print(f"{name}: 3D {solid[name]:.8g}, 2D {plane[name]:.8g}: "
          f"{d:.3g} relative (bound {bound}) {'ok' if ok else 'FAIL'}")
sys.exit(1 if failed else 0)
