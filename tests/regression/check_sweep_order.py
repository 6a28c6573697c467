#!/usr/bin/python3
"""A sweep on one rank takes its points fastest first: the progress lines
of its log ("v/c ... [k/N]") must come in order of falling speed.

usage: check_sweep_order.py LOG
"""
import re
import sys

lines = [line for line in open(sys.argv[1]) if re.search(r"\[\d+/\d+", line)]
speeds = [float(line.split()[0]) for line in lines]
if len(speeds) < 2:
    sys.exit(f"{len(speeds)} progress lines in {sys.argv[1]}: nothing to order")
if speeds != sorted(speeds, reverse=True):
    sys.exit(f"points taken in the order {speeds}, not fastest first")
print(f"{len(speeds)} points taken fastest first: {speeds}")
