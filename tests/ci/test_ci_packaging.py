#!/usr/bin/env python3
"""The pre-commit hooks (.pre-commit-hooks.yaml) and the GitHub Action (action.yml) run as their files say
(issue 33 item 6): each hook's entry on the files its pattern selects, and the action's check step with its
inputs, against the built sphdeck. Exit 0 when every expectation holds."""
import argparse, json, os, re, shlex, subprocess, sys, tempfile

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLEAN = ["decks/demo/dam_break_2d.k", "decks/demo/water_tank/water_tank.k", "decks/run/water_column_2d.k"]
MISTAKES = "decks/demo/sph_mistakes_2d.k"


def run(command, env, cwd=ROOT):
    return subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True, timeout=300)


def fuzz_lists_agree():
    """Every fuzz target of fuzz/CMakeLists.txt is built by CI (.ci/run), run by fuzz/run_fuzz.sh's default list,
    known to fuzz_dictionary and listed in fuzz/README.md's table; CI's fuzz time stays within 270 s."""
    read = lambda name: open(os.path.join(ROOT, name)).read()
    targets = re.search(r"foreach\(target ([^)]*)\)", read("fuzz/CMakeLists.txt")).group(1).split()
    ci, script, dictionary, readme = read(".ci/run"), read("fuzz/run_fuzz.sh"), read("fuzz/make_dictionary.cpp"), \
        read("fuzz/README.md")
    default = re.search(r"&& targets=\(([^)]*)\)", script).group(1).split()
    out = []
    for t in targets:
        if f"fuzz_{t}" not in ci.split():
            out.append(f"fuzz: .ci/run does not build fuzz_{t}")
        if t not in default:
            out.append(f"fuzz: run_fuzz.sh's default list leaves out {t}")
        if f'"{t}"' not in dictionary:
            out.append(f"fuzz: fuzz_dictionary does not know {t}")
        if f"| `{t}`" not in readme:
            out.append(f"fuzz: fuzz/README.md's table leaves out {t}")
    seconds = int(re.search(r"run_fuzz\.sh -s -B build-fuzz -t (\d+)", ci).group(1))
    if seconds * len(targets) > 270:  # 6 targets of 45 s before the read targets (issue 38)
        out.append(f"fuzz: CI fuzzes {len(targets)} targets x {seconds} s, more than 270 s")
    return out


def install_deps_on_fresh_machine():
    """scripts/install-deps.sh on a machine where some packages were never installed: dpkg-query then exits 1
    (as Debian's does for a name it has no record of) and the script must go on to install exactly the
    missing ones, not stop (it did, under pipefail, so `make demo` failed on a fresh Debian 12)."""
    out = []
    with tempfile.TemporaryDirectory() as work:
        fake = {
            # cmake and python3 installed, the rest unknown to dpkg: exit 1 as the real dpkg-query does.
            "dpkg-query": "printf 'cmake:install ok installed python3:install ok installed '; "
                          "echo 'dpkg-query: no packages found matching tao-pegtl-dev' >&2; exit 1",
            "apt-get": f'echo "$@" >> {work}/apt.log',
            "id": "echo 0",
        }
        for name, body in fake.items():
            path = os.path.join(work, name)
            with open(path, "w") as f:
                f.write("#!/bin/sh\n" + body + "\n")
            os.chmod(path, 0o755)
        env = dict(os.environ, PATH=work + os.pathsep + os.environ["PATH"])
        done = run(["bash", os.path.join(ROOT, "scripts/install-deps.sh"), "--build"], env)
        log = open(os.path.join(work, "apt.log")).read() if os.path.exists(os.path.join(work, "apt.log")) else ""
        installs = [line.split() for line in log.splitlines() if line.startswith("install")]
        if done.returncode != 0:
            out.append(f"install-deps on a fresh machine: exit {done.returncode}: {done.stderr[-300:]}")
        elif len(installs) != 1 or "tao-pegtl-dev" not in installs[0] or "cmake" in installs[0] \
                or "python3" in installs[0]:
            out.append(f"install-deps on a fresh machine: apt-get calls {log!r}, expected one install of the "
                       "missing packages only")
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--sphdeck", required=True)
    args = parser.parse_args()
    env = dict(os.environ, PATH=os.path.dirname(os.path.abspath(args.sphdeck)) + os.pathsep + os.environ["PATH"])
    failures = []

    hooks = yaml.safe_load(open(os.path.join(ROOT, ".pre-commit-hooks.yaml")))
    ids = {h["id"] for h in hooks}
    if ids != {"sphdeck-check", "sphdeck-format"}:
        failures.append(f"hooks: expected sphdeck-check and sphdeck-format, found {sorted(ids)}")
    for hook in hooks:
        pattern = re.compile(hook["files"])
        selected = [f for f in CLEAN if pattern.search(f)]
        if selected != CLEAN:
            failures.append(f"{hook['id']}: its files pattern does not select the shipped decks")
        done = run(shlex.split(hook["entry"]) + selected, env)  # pre-commit appends the staged files
        if done.returncode != 0:
            failures.append(f"{hook['id']} on the shipped decks: exit {done.returncode}: {done.stderr[-300:]}")
    check_hook = next(h for h in hooks if h["id"] == "sphdeck-check")
    done = run(shlex.split(check_hook["entry"]) + [MISTAKES], env)
    if done.returncode != 1 or "[SPH030]" not in done.stdout:
        failures.append(f"sphdeck-check on {MISTAKES}: exit {done.returncode}, expected 1 with SPH030")

    action = yaml.safe_load(open(os.path.join(ROOT, "action.yml")))
    step = next(s for s in action["runs"]["steps"] if s.get("name") == "check")
    for fmt in ("github", "sarif"):
        script = step["run"]
        for name, value in (("paths", MISTAKES), ("format", fmt), ("args", "--select SPH,REF")):
            script = script.replace("${{ inputs.%s }}" % name, value)
        with tempfile.TemporaryDirectory() as work:
            done = subprocess.run(["bash", "-c", f"cd {shlex.quote(ROOT)} && " + script.replace(
                "sphdeck.sarif", os.path.join(work, "sphdeck.sarif"))], env=env, capture_output=True, text=True,
                timeout=300)
            if done.returncode != 1:
                failures.append(f"action, format {fmt}: exit {done.returncode}, expected 1 (findings)")
            if fmt == "github" and "::error file=decks/demo/sph_mistakes_2d.k,line=20" not in done.stdout:
                failures.append("action, format github: no annotation for line 20 (SPH030)")
            if fmt == "sarif":
                try:
                    sarif = json.load(open(os.path.join(work, "sphdeck.sarif")))
                    rules = {r["ruleId"] for r in sarif["runs"][0]["results"]}
                    if "SPH030" not in rules or any(not r.startswith(("SPH", "REF")) for r in rules):
                        failures.append(f"action, format sarif: results {sorted(rules)}")
                except (OSError, ValueError, KeyError, IndexError) as e:
                    failures.append(f"action, format sarif: no SARIF file written ({e})")
    # The key of the cached build: the runner's system and the hash of the action's files, the same twice.
    key_step = next(s for s in action["runs"]["steps"] if s.get("id") == "key")
    keys = []
    with tempfile.TemporaryDirectory() as work:
        for _ in range(2):
            output = os.path.join(work, "output")
            open(output, "w").close()
            run(["bash", "-c", key_step["run"]], dict(env, GITHUB_ACTION_PATH=ROOT, GITHUB_OUTPUT=output))
            keys.append(open(output).read().strip())
    if not re.fullmatch(r"key=sphdeck-\S+-\S+-[0-9a-f]{20}", keys[0]) or keys[0] != keys[1]:
        failures.append(f"action, build key: {keys}, expected the same key=sphdeck-SYSTEM-ARCH-HASH twice")
    failures += fuzz_lists_agree()
    failures += install_deps_on_fresh_machine()
    for f in failures:
        print("FAIL " + f)
    print(f"ci packaging: {'passed' if not failures else 'failed'} (2 hooks, 2 action formats)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
