#!/usr/bin/python3
"""Every package a ./run.sh command's CMake configuration needs is on that command's install list.

A command installs exactly its own list (run.sh), so a library that CMake requires but that only
another command's list brings is found on a machine that ran the other command first and missed
on a fresh one: `./run.sh package` once lacked libquadrule-dev and libquantlib0-dev, and CI hid it
because the test stage had installed them. Here each command's preset is configured into a scratch
folder with CMake's JSON trace; every REQUIRED find_package, find_path and find_library of this
repository's CMake files, and the C++ compiler, is mapped to the Debian package owning what it
found (dpkg -S), and that package must be on the command's list or among the installed
dependencies of a package on it (Depends and Pre-Depends, alternatives and Provides resolved
against what is installed).

usage: check_install_lists.py SOURCE_DIR SCRATCH_DIR [PRESET ...]
With presets named, only the commands that configure one of them are checked (the sanitize build
checks its own preset: README command 2's build has checked the others). Exit 0 when every configured command is covered, 1 naming each miss. A preset whose compiler is not
installed (clang++ before `./run.sh sanitize` installed it) cannot be configured and is skipped,
said on stdout; it is checked by the stage that installs it, which runs this test too.
"""
import functools
import json
import os
import re
import shutil
import subprocess
import sys

# The commands of run.sh that configure a CMake preset: command -> preset.
COMMANDS = {"bench": "release", "benchmarks": "release", "test": "test", "sanitize": "sanitize",
            "fuzz": "sanitize", "package": "package"}
FINDS = {"find_package", "find_path", "find_library", "find_program"}
# find_package through CMake's own find modules, which cache what they found under other names
# than <name>_DIR: (cache variable, file inside it) per component. FindPython3 (the Python module
# of bench/python/): the C headers (Development.Module) and numpy's.
MODULE_FINDS = {"Python3": [("_Python3_INCLUDE_DIR", "Python.h"),
                            ("_Python3_NumPy_INCLUDE_DIR", "numpy/arrayobject.h")]}


def run(args, **kw):
    return subprocess.run(args, capture_output=True, text=True, **kw)


def required_finds(trace_file, source_dir):
    """(command, name, result variable, file looked for) of each REQUIRED find in this repository's CMake files."""
    finds = []
    with open(trace_file, encoding="utf-8") as trace:
        for line in trace:
            event = json.loads(line)
            if event.get("cmd", "").lower() not in FINDS:
                continue
            if not event.get("file", "").startswith(source_dir + os.sep):
                continue  # a package's own config file: its dependencies are the package's
            args = event.get("args", [])
            if "REQUIRED" not in args:
                continue
            name = args[0]
            command = event["cmd"].lower()
            variable = f"{name}_DIR" if command == "find_package" else name
            # find_path's result is a directory many packages share (/usr/include): what it
            # looked for inside it is the file that names the package.
            inside = None
            if command == "find_path":
                inside = args[2] if args[1] == "NAMES" else args[1]
            finds.append((command, name, variable, inside))
            # A find module that caches no <name>_DIR: the files it found, one per component.
            for variable, inside in MODULE_FINDS.get(name, []):
                finds.append((command, name, variable, inside))
    return finds


def cache_of(build_dir):
    values = {}
    with open(os.path.join(build_dir, "CMakeCache.txt"), encoding="utf-8") as cache:
        for line in cache:
            m = re.match(r"^([^#/][^:=]*):[A-Z]+=(.*)$", line.rstrip("\n"))
            if m:
                values[m.group(1)] = m.group(2)
    return values


# Presets share most finds (fmt, Boost, the compiler): each path is asked of dpkg once, since a
# `dpkg -S` reads the whole file list database (a quarter of a second each).
@functools.cache
def owner(path):
    """The installed package that owns `path` (symlinks followed: /usr/bin/c++ is an alternative)."""
    for candidate in (path, os.path.realpath(path)):
        result = run(["dpkg", "-S", candidate])
        if result.returncode == 0:
            return result.stdout.split(":")[0].split(",")[0].strip()
    return None


class Installed:
    """Depends and Provides of the installed packages, from dpkg's status."""

    def __init__(self):
        out = run(["dpkg-query", "-W", "-f",
                   "${Package}\t${Status}\t${Depends}, ${Pre-Depends}\t${Provides}\n"]).stdout
        self.depends, self.providers = {}, {}
        for line in out.splitlines():
            package, status, depends, provides = (line.split("\t") + ["", "", ""])[:4]
            if not status.endswith("installed") or "deinstall" in status:
                continue
            self.depends[package] = [[re.split(r"[\s(:]", alt.strip())[0] for alt in group.split("|")]
                                     for group in depends.split(",") if group.strip()]
            for p in provides.split(","):
                if p.strip():
                    self.providers.setdefault(re.split(r"[\s(:]", p.strip())[0], []).append(package)

    def resolve(self, name):
        if name in self.depends:
            return [name]
        return self.providers.get(name, [])

    def closure(self, roots):
        seen, todo = set(), [p for r in roots for p in self.resolve(r)]
        while todo:
            package = todo.pop()
            if package in seen:
                continue
            seen.add(package)
            for group in self.depends.get(package, []):
                for alternative in group:
                    installed = self.resolve(alternative)
                    if installed:
                        todo.extend(installed)
                        break
        return seen


def preset_compiler(source_dir, name):
    """CMAKE_CXX_COMPILER of a configure preset (following `inherits`), or None."""
    with open(os.path.join(source_dir, "CMakePresets.json"), encoding="utf-8") as f:
        presets = {p["name"]: p for p in json.load(f)["configurePresets"]}
    todo = [name]
    while todo:
        preset = presets[todo.pop(0)]
        compiler = preset.get("cacheVariables", {}).get("CMAKE_CXX_COMPILER")
        if compiler:
            return compiler
        inherits = preset.get("inherits", [])
        todo.extend([inherits] if isinstance(inherits, str) else inherits)
    return None


def main():
    source_dir, scratch = os.path.realpath(sys.argv[1]), sys.argv[2]
    only = set(sys.argv[3:])
    unknown = only - set(COMMANDS.values())
    if unknown:
        print(f"check_install_lists.py: unknown preset(s) {', '.join(sorted(unknown))}; expected "
              f"some of {', '.join(sorted(set(COMMANDS.values())))}")
        return 2
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    installed = Installed()
    misses, checked, configured = [], [], {}
    for command, preset in COMMANDS.items():
        if only and preset not in only:
            continue
        listed = run([os.path.join(source_dir, "run.sh"), "packages", command]).stdout.split()
        if not listed:
            misses.append(f"./run.sh packages {command} prints no install list")
            continue
        if preset not in configured:
            compiler = preset_compiler(source_dir, preset)
            if compiler and shutil.which(compiler) is None:
                print(f"{preset}: its compiler {compiler} is not installed here; skipped")
                configured[preset] = None
                continue
            build_dir = os.path.join(scratch, preset)
            trace = os.path.join(scratch, f"{preset}.trace.json")
            result = run(["cmake", "--preset", preset, "-B", build_dir, "-DQUADMC_CCACHE=OFF",
                          "--trace-format=json-v1", f"--trace-redirect={trace}"], cwd=source_dir)
            if result.returncode != 0:
                misses.append(f"preset {preset} does not configure:\n{result.stderr}")
                configured[preset] = None
                continue
            configured[preset] = (required_finds(trace, source_dir), cache_of(build_dir))
        if configured[preset] is None:
            continue
        finds, cache = configured[preset]
        covered = installed.closure(listed)
        found = [("compiler", "CMAKE_CXX_COMPILER", "CMAKE_CXX_COMPILER", None)] + finds
        for kind, name, variable, inside in found:
            path = cache.get(variable, "")
            if not path or path.endswith("-NOTFOUND") or not os.path.isabs(path):
                continue  # Threads and the like: nothing on disk to own
            if inside:
                path = os.path.join(path, inside)
            elif os.path.isdir(path):
                # A package's CMake folder: its config file, owned by that package alone.
                configs = sorted(f for f in os.listdir(path) if f.lower().endswith("config.cmake"))
                path = os.path.join(path, configs[0]) if configs else path
            package = owner(path)
            if package is None:
                misses.append(f"{command}: {kind}({name}) found {path}, which no package owns")
            elif package not in covered:
                misses.append(f"./run.sh {command} (preset {preset}): {kind}({name}) found {path}, "
                              f"from {package}, which neither its install list nor their "
                              f"dependencies bring")
        checked.append(f"{command} ({preset}, {len(found)} finds)")
    print("checked:", ", ".join(checked))
    for m in misses:
        print("MISSING:", m)
    return 1 if misses or not checked else 0


if __name__ == "__main__":
    sys.exit(main())
