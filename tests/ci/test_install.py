#!/usr/bin/env python3
"""The installed sphdeck works as the build tree's (issue 42): `cmake --install` into a temporary root, or,
with --deb, the Debian package unpacked there (dpkg -x). Then:
  - the installed binary prints what the build tree's binary prints on decks/demo/sph_mistakes_2d.k;
  - `man sphdeck-check` (MANPATH in the root) shows the check command's options;
  - the bash completion lists the subcommands, and a subcommand's options;
  - with --deb: every shared library the binary loads comes from a package the .deb depends on.
Exit 0 when every expectation holds."""
import argparse, os, re, shutil, subprocess, sys, tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DECK = "decks/demo/sph_mistakes_2d.k"
SUBCOMMANDS = {"check", "rule", "rules", "keyword", "format", "dump", "diff", "smooth", "sol2sph", "run",
               "verify", "lsp", "mcp"}


def run(command, **kwargs):
    return subprocess.run(command, capture_output=True, text=True, timeout=120, **kwargs)


def same_report(text):
    """The report without the run time of its summary line ("... in 0.01 s")."""
    return re.sub(r" in \d+\.\d+ s$", "", text, flags=re.M)


def install_tree(build, root, failures):
    done = run(["cmake", "--build", build, "--target", "sphdeck_man"])
    if done.returncode != 0:
        failures.append(f"building the man pages: exit {done.returncode}: {done.stderr[-300:]}")
        return
    done = run(["cmake", "--install", build, "--prefix", "/usr"], env=dict(os.environ, DESTDIR=root))
    if done.returncode != 0:
        failures.append(f"cmake --install: exit {done.returncode}: {done.stderr[-300:]}")


def check_depends(deb, binary, failures):
    depends = run(["dpkg-deb", "-f", deb, "Depends"]).stdout
    named = {d.strip().split()[0] for d in depends.split(",") if d.strip()}
    for needed in ("libfmt9", "libtomlplusplus3", "libgomp1", "libstdc++6"):
        if needed not in named:
            failures.append(f"package: Depends lacks {needed} ({depends.strip()})")
    for line in run(["ldd", binary]).stdout.splitlines():
        match = re.search(r"=> (/\S+)", line)
        if not match:
            continue
        owner = run(["dpkg", "-S", os.path.realpath(match.group(1))])
        if owner.returncode != 0:  # try the path as ldd printed it (/lib vs /usr/lib)
            owner = run(["dpkg", "-S", match.group(1)])
        package = owner.stdout.split(":")[0].strip() if owner.returncode == 0 else "?"
        if package not in named:
            failures.append(f"package: {match.group(1)} comes from '{package}', not in Depends ({depends.strip()})")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--sphdeck", required=True, help="the build tree's binary")
    parser.add_argument("--deb", help="check this Debian package (dpkg -x) instead of cmake --install")
    args = parser.parse_args()
    build = os.path.dirname(os.path.abspath(args.sphdeck))
    failures = []
    with tempfile.TemporaryDirectory() as root:
        if args.deb:
            done = run(["dpkg", "-x", args.deb, root])
            if done.returncode != 0:
                failures.append(f"dpkg -x {args.deb}: exit {done.returncode}: {done.stderr[-300:]}")
        else:
            install_tree(build, root, failures)
        installed = os.path.join(root, "usr", "bin", "sphdeck")
        if not os.access(installed, os.X_OK):
            print(f"FAIL: no installed binary at {installed}\n" + "\n".join(failures), file=sys.stderr)
            return 1
        if args.deb:
            check_depends(args.deb, installed, failures)

        ours, theirs = (run([binary, "check", "--no-config", DECK], cwd=ROOT) for binary in (installed, args.sphdeck))
        if (ours.returncode, same_report(ours.stdout)) != (theirs.returncode, same_report(theirs.stdout)):
            failures.append(f"installed check on {DECK}: exit {ours.returncode} and its report differ from the build "
                            f"tree's (exit {theirs.returncode})")
        if ours.returncode != 1 or "[SPH030]" not in ours.stdout:
            failures.append(f"installed check on {DECK}: exit {ours.returncode}, expected 1 with SPH030")

        env = dict(os.environ, MANPATH=os.path.join(root, "usr", "share", "man"), MANWIDTH="100", MANPAGER="cat",
                   PAGER="cat", PATH=os.path.dirname(installed) + os.pathsep + os.environ["PATH"])
        if shutil.which("man"):
            page = run(["man", "sphdeck-check"], env=env)
            if page.returncode != 0 or "SYNOPSIS" not in page.stdout or "--fail-on" not in page.stdout:
                failures.append(f"man sphdeck-check: exit {page.returncode}, no SYNOPSIS or --fail-on: "
                                f"{(page.stdout + page.stderr)[:300]}")
        else:
            failures.append("no `man` to show the page (scripts/install-deps.sh installs man-db)")
        for sub in SUBCOMMANDS:
            if not os.path.exists(os.path.join(root, "usr", "share", "man", "man1", f"sphdeck-{sub}.1")):
                failures.append(f"no man page sphdeck-{sub}.1")

        completion = os.path.join(root, "usr", "share", "bash-completion", "completions", "sphdeck")
        script = (f"source {completion}\n"
                  "COMP_WORDS=(sphdeck ''); COMP_CWORD=1; _sphdeck; echo \"${COMPREPLY[*]}\"\n"
                  "COMP_WORDS=(sphdeck check --fail); COMP_CWORD=2; _sphdeck; echo \"${COMPREPLY[*]}\"\n")
        done = run(["bash", "-c", script], env=env)
        lines = done.stdout.splitlines() + ["", ""]
        if set(lines[0].split()) != SUBCOMMANDS:
            failures.append(f"bash completion of 'sphdeck ': {lines[0]!r}, expected {sorted(SUBCOMMANDS)}")
        if lines[1].split() != ["--fail-on"]:
            failures.append(f"bash completion of 'sphdeck check --fail': {lines[1]!r}, expected --fail-on")
        zsh_completion = os.path.join(root, "usr", "share", "zsh", "vendor-completions", "_sphdeck")
        if not os.path.exists(zsh_completion):
            failures.append("no zsh completion")
        elif shutil.which("zsh") and run(["zsh", "-n", zsh_completion]).returncode != 0:
            failures.append("the zsh completion does not parse (zsh -n)")
        for shipped in ("share/doc/sphdeck/rules/SPH030.md", "share/sphdeck/editors/neovim/lua/sphdeck.lua",
                        "share/sphdeck/decks/verification/sod_2d_200.k"):
            if not os.path.exists(os.path.join(root, "usr", shipped)):
                failures.append(f"not installed: /usr/{shipped}")

    for f in failures:
        print("FAIL:", f, file=sys.stderr)
    print(f"install check ({'package ' + args.deb if args.deb else 'cmake --install'}): "
          f"{'ok' if not failures else f'{len(failures)} failure(s)'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
