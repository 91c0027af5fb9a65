#!/usr/bin/env python3
"""Holds the documentation to the program: every `columba SUBCOMMAND ...` command that README.md
and docs/*.md show (in shell blocks and in inline code) must name a subcommand that exists and only
options that subcommand's --help lists. Prints each mismatch with file and line; exit status 1 if
any. Usage: check-doc-commands.py COLUMBA_BINARY REPOSITORY_DIR"""
import pathlib
import re
import shlex
import subprocess
import sys


def commands(text):
    """(line number, command text) of every columba command in `text`."""
    in_shell = False
    for number, line in enumerate(text.splitlines(), 1):
        stripped = line.strip()
        if stripped.startswith("```"):
            in_shell = not in_shell and stripped[3:].strip() in ("sh", "bash", "console", "shell", "")
            continue
        if in_shell:
            command = re.sub(r"^\$\s*", "", stripped.split(" #")[0])
            if re.match(r"^(build/|\./)?columba\s", command):
                yield number, command
        for span in re.findall(r"`((?:build/)?columba [^`]+)`", line):
            yield number, span


def options_of(help_text):
    return set(re.findall(r"(--[A-Za-z0-9][A-Za-z0-9_-]*)", help_text)) | set(re.findall(r"\s(-[A-Za-z])[,\s]", help_text))


def main():
    binary, repo = sys.argv[1], pathlib.Path(sys.argv[2])
    top = subprocess.run([binary, "--help"], capture_output=True, text=True).stdout
    subcommands = set(re.findall(r"^\s{2}([a-z]+)\s", top, re.MULTILINE))
    helps = {}
    problems = 0
    checked = 0
    for page in [repo / "README.md", *sorted((repo / "docs").glob("*.md"))]:
        for number, command in commands(page.read_text(encoding="utf-8")):
            try:
                words = shlex.split(command)
            except ValueError:
                words = command.split()
            words = [w.strip("[]|,") for w in words]
            if len(words) < 2 or words[1].startswith("-") or words[1] in ("...", ""):
                continue
            sub = words[1]
            where = f"{page.relative_to(repo)}:{number}"
            if sub not in subcommands:
                print(f"{where}: 'columba {sub}' is not a subcommand (known: {', '.join(sorted(subcommands))})")
                problems += 1
                continue
            if sub not in helps:
                helps[sub] = options_of(subprocess.run([binary, sub, "--help"], capture_output=True, text=True).stdout)
            for word in words[2:]:
                option = word.split("=")[0]
                if re.fullmatch(r"--[A-Za-z0-9][A-Za-z0-9_-]*", option) and option not in helps[sub] and option != "--help":
                    print(f"{where}: 'columba {sub}' has no option {option}")
                    problems += 1
            checked += 1
    print(f"{checked} commands in the documentation checked, {problems} mismatches")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
