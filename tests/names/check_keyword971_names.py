#!/usr/bin/env python3
"""No keyword name of OpenRadioss' Keyword971 CFG files is a DK001 error (issue 37, docs/rules/DK001.md).

The names come from the CFG files of an OpenRadioss checkout when SPHDECK_OPENRADIOSS names one (its root
folder; read as scripts/gen_keyword971_names.py reads them), else from the committed table
grammar/keywords/generated/keyword971_names.cpp. Every name becomes one block of a deck that
`sphdeck check --format json` reads; the test fails on any DK001 error, naming the blocks.

Usage: check_keyword971_names.py --sphdeck build/sphdeck
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TABLE = os.path.join(ROOT, 'grammar', 'keywords', 'generated', 'keyword971_names.cpp')


def names_from_checkout(checkout):
    sys.path.insert(0, os.path.join(ROOT, 'scripts'))
    import gen_keyword971_names  # noqa: E402 (the generator's own reading)
    return gen_keyword971_names.read_names(os.path.join(checkout, 'hm_cfg_files', 'config', 'CFG'))


def names_from_table():
    with open(TABLE, encoding='utf-8') as f:
        return re.findall(r'^    "(\*[^"]+)"sv,$', f.read(), re.M)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('--sphdeck', required=True)
    a = p.parse_args()
    checkout = os.environ.get('SPHDECK_OPENRADIOSS')
    names = names_from_checkout(checkout) if checkout else names_from_table()
    source = f'the CFG files of {checkout}' if checkout else 'the committed table'
    if len(names) < 500:  # the table holds ~760: far fewer means the reading broke
        print(f'only {len(names)} names read from {source}')
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        deck = os.path.join(tmp, 'keyword971_names.k')
        with open(deck, 'w', encoding='utf-8') as f:
            f.write('*KEYWORD\n' + ''.join(n + '\n' for n in names) + '*END\n')
        run = subprocess.run([a.sphdeck, 'check', '--format', 'json', '--no-config', deck],
                             capture_output=True, text=True)
        if run.returncode not in (0, 1):
            print(run.stdout, run.stderr)
            return 1
        report = json.loads(run.stdout)
    errors = [d for d in report['diagnostics'] if d['code'] == 'DK001' and d['severity'] == 'error']
    for d in errors:
        print(f"line {d['line']}: {d['message']}")
    print(f'{len(names)} names from {source}: {len(errors)} DK001 errors')
    return 1 if errors else 0


if __name__ == '__main__':
    sys.exit(main())
