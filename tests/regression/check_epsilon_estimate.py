#!/usr/bin/python3
"""The convergence study's epsilon, with its error bar, covers a reference.

usage: check_epsilon_estimate.py epsilon_estimate.csv REFERENCE
"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1], newline="")))
total = next(row for row in rows if row["factor"] == "total")
epsilon, error = float(total["limit"]), float(total["error"])
reference = float(sys.argv[2])
print(f"epsilon = {epsilon:.6f} +- {error:.2e}, reference {reference:.6f}, "
      f"distance {abs(epsilon - reference):.2e}")
ok = 0.0 < error and abs(epsilon - reference) <= error
print("OK" if ok else "FAIL")
sys.exit(0 if ok else 1)
