#!/usr/bin/env python3
"""One CLI grammar: walks every subcommand's --help and checks that the shared flags mean the
same thing everywhere (src/app/cli_options.hpp):
  -o,--output  "FILE: ..."        --csv  "[FILE]: ..." (an optional value)
  --set        "KEY=VALUE..."     -q,--quiet  "No progress bar and no summary"
  --threads    "N: worker threads..."
and that every command that reads a case (positional `case` or --case) takes --set.
Usage: cli_grammar.py GEARTRIB"""
import re
import subprocess
import sys

binary = sys.argv[1]
failures = []


def help_of(path):
    out = subprocess.run([binary, *path, "--help"], capture_output=True, text=True, check=True).stdout
    return out


def entries(text, section):
    """(names, description) per entry of a CLI11 help section ('Options' or 'Positionals')."""
    found, current = [], None
    in_section = False
    for line in text.splitlines():
        if re.match(r"^\S.*:$", line):
            in_section = line.startswith(section)
            current = None
            continue
        if not in_section or not line.strip():
            continue
        m = re.match(r"^  (\S+)(?: [^ ].*?)?(?:\s{2,}(.*))?$", line)
        if m and not line.startswith("   "):
            current = [m.group(1), (m.group(2) or "").strip()]
            found.append(current)
        elif current is not None:
            current[1] = (current[1] + " " + line.strip()).strip()
    return found


def subcommands(text):
    names, in_section = [], False
    for line in text.splitlines():
        if re.match(r"^\S.*:$", line):
            in_section = line.startswith("Subcommands")
            continue
        m = re.match(r"^  (\S+)\s{2,}", line)
        if in_section and m:
            names.append(m.group(1))
    return names


RULES = {
    "-o,--output": lambda d: d.startswith("FILE: "),
    "--csv": lambda d: d.startswith("[FILE]: "),
    "--set": lambda d: d.startswith("KEY=VALUE"),
    "-q,--quiet": lambda d: d == "No progress bar and no summary",
    "--threads": lambda d: d.startswith("N: worker threads"),
    "--case": lambda d: d == "Case file (default: gears/m6z30.toml)",
}
# Short flags may only be these (a letter means one thing everywhere).
SHORT = {"-h": "-h,--help", "-o": "-o,--output", "-q": "-q,--quiet"}


def check(path):
    text = help_of(path)
    name = " ".join(path) or "geartrib"
    opts = entries(text, "Options")
    pos = entries(text, "Positionals")
    seen = {n for n, _ in opts}
    for n, d in opts:
        if n in RULES and not RULES[n](d):
            failures.append(f"{name}: {n}: '{d}' breaks the shared grammar")
        for short, full in SHORT.items():
            if (n == short or n.startswith(short + ",")) and n != full:
                failures.append(f"{name}: {n}: {short} must be {full}")
        for flag in ("--output", "--quiet"):
            if n == flag:
                failures.append(f"{name}: {flag} without its short form")
    reads_case = "--case" in seen or any(n == "case" for n, _ in pos)
    for n, d in pos:
        if n == "case" and d != "Case file (default: gears/m6z30.toml)":
            failures.append(f"{name}: positional case: '{d}'")
    if reads_case and "--set" not in seen:
        failures.append(f"{name}: reads a case but takes no --set")
    if "--csv" in seen and not any(n == "--csv" for n, _ in opts):
        failures.append(f"{name}: --csv")
    checked = 1
    for sub in subcommands(text):
        checked += check([*path, sub])
    return checked


count = check([])
# --csv takes an optional value: without one it is a format switch (exit 0, CSV on stdout).
out = subprocess.run([binary, "asperity", "--delta-star", "1", "--csv"], capture_output=True, text=True)
if out.returncode != 0 or not out.stdout.startswith("delta_star"):
    failures.append(f"asperity --csv without a file: exit {out.returncode}, '{out.stdout[:40]}'")
for f in failures:
    print("FAIL", f)
print(f"{count} command helps walked, {len(failures)} breaches")
sys.exit(1 if failures else 0)
