#!/usr/bin/python3
"""check_family_includes: the library's families include one way.

Usage: check_family_includes.py IMAGEOPS_SRC_DIR

Every file of imageops/src lives in a family folder; a file may include
internal headers ("family/name.h") of its own family and of the families it
builds on, never of a family that builds on it. Fails (exit 1), naming the
file, the line and the header, on an include against that order, on an
internal header named without its family, on one that does not exist, and
on a file outside the family folders.
"""
import os
import re
import sys

# Each family and the families it may include (besides its own).
BUILDS_ON = {
    "core": set(),
    "walkers": {"core"},
    "report": {"core", "walkers"},
    "features": {"core", "walkers"},
    "denoise": {"core", "walkers", "features"},
    "shots": {"core", "walkers", "features", "denoise"},
    "passes": {"core", "walkers", "features", "denoise"},
    "network": {"core"},
    "metrics": {"core"},
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def problems(src):
    """Yields one message per include against the families' order."""
    for family in sorted(os.listdir(src)):
        folder = os.path.join(src, family)
        if not os.path.isdir(folder):
            yield f"{family}: a file outside the family folders"
            continue
        if family not in BUILDS_ON:
            yield f"{family}/: a folder this check does not know; add it to BUILDS_ON"
            continue
        for name in sorted(os.listdir(folder)):
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if not m:
                        continue
                    header = m.group(1)
                    where = f"{family}/{name}:{number}: \"{header}\""
                    parts = header.split("/")
                    if len(parts) != 2:
                        yield f"{where}: name internal headers by their family"
                    elif not os.path.isfile(os.path.join(src, header)):
                        yield f"{where}: no such header"
                    elif parts[0] != family and parts[0] not in BUILDS_ON[family]:
                        yield f"{where}: {family} does not build on {parts[0]}"


def main():
    found = list(problems(sys.argv[1]))
    for message in found:
        print(message)
    print(f"{len(found)} includes against the families' order")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
