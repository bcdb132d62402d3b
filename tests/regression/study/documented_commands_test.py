#!/usr/bin/python3
"""The commands the documentation tells a user to type start with a program that runs as typed: every
`scripts/...` word that begins a command line in the README files and in the examples' "Sample run" headers
names a file in the repository that is executable (git keeps the mode) and, for a script, has a `#!` line
whose interpreter exists. Found when the README's `scripts/hybrid_run.py ...` answered "Permission denied"
from a fresh clone (the file was committed without its x bit).
"""
import argparse
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checklist import Checklist  # noqa: E402

# A command line: optional leading spaces, an optional "# " (the Tcl headers) and the program word.
COMMAND_RE = re.compile(r"^\s*(?:#\s+)?(scripts/\S+\.(?:py|sh))(?:\s|$)")


def documented_programs(repo):
    docs = glob.glob(os.path.join(repo, "**", "README.md"), recursive=True)
    docs += glob.glob(os.path.join(repo, "scripts", "examples", "*.tcl"))
    found = {}
    for doc in docs:
        top = os.path.relpath(doc, repo).split(os.sep)[0]
        if top.startswith("build") or top == "results":  # build trees and run outputs are not documentation
            continue
        with open(doc, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = COMMAND_RE.match(line)
                if m:
                    found.setdefault(m.group(1), "%s:%d" % (os.path.relpath(doc, repo), number))
    return found


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", default=None)
    ap.add_argument("--repo", required=True)
    args = ap.parse_args()
    check = Checklist()
    programs = documented_programs(args.repo)
    check.expect("the documentation names programs", len(programs) >= 3, "(%d)" % len(programs))
    for program, where in sorted(programs.items()):
        path = os.path.join(args.repo, program)
        if not check.expect("%s (%s) exists" % (program, where), os.path.isfile(path)):
            continue
        check.expect("%s is executable" % program, os.access(path, os.X_OK))
        with open(path, "rb") as f:
            first = f.readline().decode("utf-8", "replace").strip()
        interpreter = first[2:].split()[0] if first.startswith("#!") and len(first) > 2 else ""
        check.expect("%s starts with #! and an interpreter that exists" % program,
                     bool(interpreter) and os.access(interpreter, os.X_OK), "(%r)" % first)
    return check.exit_status()


if __name__ == "__main__":
    sys.exit(main())
