#!/usr/bin/env python3
"""The folder rule of docs/architecture.md: a file in include/ssc/F/ or
source/F/ includes <ssc/G/...> only if G comes no later than F in LAYERS, so
the library reads top-down and its folder include graph has no cycle. The
application level (include/ssc/*.h, source/*.cc, app/) may include every
folder; no folder may include the application level.

Prints every violation as "file:line: F includes G" and exits 1 if there is
one; exits 0 with a one-line summary otherwise.
"""
import pathlib
import re
import sys

LAYERS = ["base", "mesh", "microstructure", "embedding", "materials",
          "linear_algebra", "multigrid", "mechanics", "contact", "nonlinear",
          "output", "scenes", "identification"]
APPLICATION = len(LAYERS)
INCLUDE = re.compile(r'^\s*#\s*include\s*<ssc/([^>]+)>')


def level(relative_path, where):
    """Index of the folder of @p relative_path (below include/ssc/ or
    source/) in LAYERS, APPLICATION for a file at the top."""
    parts = pathlib.PurePosixPath(relative_path).parts
    if len(parts) == 1:
        return APPLICATION
    if parts[0] not in LAYERS:
        sys.exit(f"{where}: folder '{parts[0]}' is not in the folder rule "
                 f"({', '.join(LAYERS)}): add it to LAYERS in {__file__} "
                 "and to docs/architecture.md")
    return LAYERS.index(parts[0])


def name(index):
    return "the application level" if index == APPLICATION else LAYERS[index]


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    files = [(path, path.relative_to(root / "include" / "ssc"))
             for path in (root / "include" / "ssc").rglob("*.h")]
    files += [(path, path.relative_to(root / "source"))
              for path in (root / "source").rglob("*.cc")]
    violations, n_includes = 0, 0
    for path, relative in sorted(files):
        own = level(relative, path)
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            n_includes += 1
            where = f"{path.relative_to(root)}:{number}"
            target = level(match.group(1), where)
            if target > own:
                print(f"{where}: {name(own)} includes {name(target)} "
                      f"(<ssc/{match.group(1)}>)")
                violations += 1
    if violations:
        print(f"check_includes: {violations} include(s) break the folder "
              f"rule {' < '.join(LAYERS)} (docs/architecture.md)")
        return 1
    print(f"check_includes: {len(files)} files, {n_includes} ssc includes "
          "follow the folder rule")
    return 0


if __name__ == "__main__":
    sys.exit(main())
