#!/usr/bin/python3
"""Damage a file in place, as a failing disk or a careless copy might:
truncate (to half its size), zero (every byte 0, same size), random (every
byte random, same size), flip (8 bytes inverted in the middle) or flipN
(8 bytes inverted at N/10 of the file, N = 0..9). Used by
tests/checkpoint_damage.sh and scripts/fault_sweep.sh.

Usage: damage_file.py FILE MODE"""
import os
import sys

path, mode = sys.argv[1], sys.argv[2]
size = os.path.getsize(path)
if mode == "truncate":
    os.truncate(path, size // 2)
elif mode == "zero":
    with open(path, "r+b") as f:
        f.write(bytes(size))
elif mode == "random":
    with open(path, "r+b") as f:
        f.write(os.urandom(size))
elif mode == "flip" or (mode.startswith("flip") and mode[4:].isdigit()):
    tenths = 5 if mode == "flip" else int(mode[4:])
    offset = max(0, size // 2 - 4) if mode == "flip" else \
        min(max(0, size - 8), size * tenths // 10)
    with open(path, "r+b") as f:
        f.seek(offset)
        data = f.read(8)
        f.seek(offset)
        f.write(bytes(b ^ 0xFF for b in data))
else:
    sys.exit(f"damage_file.py: unknown mode '{mode}'")
