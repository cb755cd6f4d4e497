#!/usr/bin/env python3
"""The commands that README.md and the guides in doc/ promise to finish
quickly run, exit with status 0 and write the files they promise.

Usage: check_commands.py <source dir> <build dir> <work dir>

A fenced block is tested when the line before it is the HTML comment

    <!-- test-command files="a b ..." pictures="c ..." args='--set "..."' -->

(each key optional). Every line of the block is run with sh in <work dir>,
where build, parameter_files, scripts and benchmarks name the source and
build directories (so that relative paths resolve as in the source tree
and the output stays out of it); lines with a <placeholder> and the text
after "  #" are left out; args are appended to each line that runs a
program of build/, other than --help (a smaller level or fewer steps
where the guide's command takes longer). After the block the files must exist and the
pictures must pass tests/docs/check_png.py (not blank or constant).
Exits with status 1 if a command fails or times out (120 s), a file is
missing, a picture is blank, or no block is marked.
"""
import glob
import os
import re
import shlex
import shutil
import subprocess
import sys
import time

marker = re.compile(r"<!--\s*test-command\b(.*?)-->\s*\n```[^\n]*\n(.*?)```",
                    re.S)
program = re.compile(r"(^|\s)build/(willmore_flow|biharmonic_flow|"
                     r"edge_restoration|shape_from_contour)\b")


def blocks(root):
    for name in ["README.md"] + sorted(
            os.path.relpath(p, root) for p in glob.glob(f"{root}/doc/*.md")):
        text = open(os.path.join(root, name), encoding="utf-8").read()
        for match in marker.finditer(text):
            options = dict(token.split("=", 1)
                           for token in shlex.split(match.group(1)))
            line = text[:match.start()].count("\n") + 1
            yield f"{name}:{line}", options, match.group(2)


def commands(block, args):
    for line in block.splitlines():
        line = line.split("  #")[0].strip()
        if not line or re.search(r"<[^>]+>", line):
            continue
        if args and program.search(line) and "--help" not in line:
            line += " " + args
        yield line


def main(root, build, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for name, target in (("build", build),
                         ("parameter_files", f"{root}/parameter_files"),
                         ("scripts", f"{root}/scripts"),
                         ("benchmarks", f"{root}/benchmarks")):
        os.symlink(os.path.abspath(target), os.path.join(work, name))
    environment = dict(os.environ, OMP_NUM_THREADS="1")
    failures, n_commands, n_blocks = [], 0, 0
    check_png = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                             "check_png.py")
    for where, options, block in blocks(root):
        n_blocks += 1
        for command in commands(block, options.get("args", "")):
            n_commands += 1
            start = time.monotonic()
            try:
                result = subprocess.run(command, shell=True, cwd=work,
                                        env=environment, timeout=120,
                                        stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True)
                status = result.returncode
                output = result.stdout
            except subprocess.TimeoutExpired as e:
                status, output = "timeout", (e.stdout or b"").decode()
            print(f"{where}: {command}\n  -> status {status}, "
                  f"{time.monotonic() - start:.0f} s")
            if status != 0:
                print("\n".join(output.splitlines()[-20:]))
                failures.append(f"{where}: status {status}: {command}")
        for path in options.get("files", "").split():
            if not os.path.exists(os.path.join(work, path)):
                failures.append(f"{where}: no file {path}")
        pictures = [os.path.join(work, p)
                    for p in options.get("pictures", "").split()]
        if pictures and subprocess.run(
                [sys.executable, check_png] + pictures).returncode != 0:
            failures.append(f"{where}: a picture is missing or blank")
    for failure in failures:
        print("FAIL", failure)
    print(f"{n_blocks} blocks, {n_commands} commands, "
          f"{len(failures)} failures")
    return 1 if failures or n_blocks == 0 else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))
