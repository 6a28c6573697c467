#!/usr/bin/python3
"""A convergence sequence is clean, of the expected order, and its
extrapolated epsilon with its error bar contains a finer reference.

usage: check_clean_sequence.py epsilon_estimate.csv FACTOR ORDER REFERENCE
  FACTOR     the row of epsilon_estimate.csv ('mesh', 'time step', ...)
  ORDER      the order the scheme must show (within +-0.25)
  REFERENCE  epsilon of an independent, finer run
"""
import csv
import math
import sys

path, factor, order, reference = (sys.argv[1], sys.argv[2],
                                  float(sys.argv[3]), float(sys.argv[4]))
row = next(r for r in csv.DictReader(open(path, newline=""))
           if r["factor"] == factor)
clean = row["clean"] == "1"
observed = float(row["observed_order"]) if row["observed_order"] else math.nan
limit, error = float(row["limit"]), float(row["error"])
print(f"{factor}: clean {clean}, order {observed:.3f} (expected {order}), "
      f"scatter {row['order_scatter'] or '-'}; limit {limit:.9f} "
      f"+- {error:.2e}, reference {reference:.9f}, distance "
      f"{abs(limit - reference):.2e}")
ok = (clean and abs(observed - order) <= 0.25 and 0. < error
      and abs(limit - reference) <= error)
print("OK" if ok else "FAIL")
sys.exit(0 if ok else 1)
