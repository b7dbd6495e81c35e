#!/usr/bin/env python3
"""Rewrites TestCosts.cmake beside this script from a ctest log.

    tests/schedule/update_costs.py LOG [MIN_SECONDS]

LOG is what `ctest --preset release -j2` printed (its "Test #N: NAME ...
Passed  T sec" lines); every test that took at least MIN_SECONDS (default 10) gets its time
as its COST, longest first. The header comment is kept.
"""
import pathlib
import re
import sys


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    log = pathlib.Path(sys.argv[1]).read_text()
    minimum = float(sys.argv[2]) if len(sys.argv) == 3 else 10.0
    # "12/698 Test #406: NAME ......   Passed   42.10 sec"
    line = re.compile(r"Test +#\d+: (.+?) \.{3,}.*?(?:Passed|Failed|\*\*\*\w+)\s+([\d.]+) sec")
    times = sorted(((float(m.group(2)), m.group(1).rstrip()) for m in line.finditer(log)), reverse=True)
    target = pathlib.Path(__file__).with_name("TestCosts.cmake")
    header = [l for l in target.read_text().splitlines() if l.startswith("#")]
    rows = [f"set_tests_properties([=[{name}]=] PROPERTIES COST {round(t)})" for t, name in times if t >= minimum]
    target.write_text("\n".join(header + rows) + "\n")
    print(f"{target}: {len(rows)} tests of {len(times)} at or above {minimum:g} s")


if __name__ == "__main__":
    main()
