#!/usr/bin/env python3
"""Fails when an include goes against the layer order of the code.

The layers, lowest first; a file may include files of its own layer and of layers below it,
never of a layer above. Within core/, a file's layer is the first folder under core/ (and
core/intersect/clip/ is part of core/intersect).

    python3 tools/check_layers.py [repository root]
"""
import pathlib
import re
import sys

LAYERS = [
    'core/base',
    'core/numeric',
    'core/bernstein',
    'core/curve',
    'core/cubic',
    'core/measure',
    'core/intersect',
    'core/self_intersect',
    'core/loop',
    'core/path',
    'core/outline',
    'api',
    'service',
]
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.MULTILINE)


def layer_of(path):
    """The index in LAYERS of the layer holding `path` (relative to the root), or None."""
    best = None
    for index, prefix in enumerate(LAYERS):
        if path == prefix or path.startswith(prefix + '/'):
            if best is None or len(prefix) > len(LAYERS[best]):
                best = index
    return best


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else '.').resolve()
    problems = []
    for top in ('core', 'api', 'service'):
        for source in sorted((root / top).rglob('*')):
            if source.suffix not in ('.hpp', '.cpp', '.h'):
                continue
            relative = source.relative_to(root).as_posix()
            own = layer_of(relative)
            if own is None:
                problems.append(f'{relative}: not in any layer of tools/check_layers.py')
                continue
            for included in INCLUDE.findall(source.read_text(encoding='utf-8')):
                target = layer_of(included)
                if target is None:
                    if included.split('/')[0] in ('core', 'api', 'service'):
                        problems.append(f'{relative}: includes {included}, which is in no layer')
                    continue
                if target > own:
                    problems.append(f'{relative}: includes {included} ({LAYERS[target]}), '
                                    f'a layer above its own ({LAYERS[own]})')
    for problem in problems:
        print(problem)
    if problems:
        print(f'{len(problems)} include(s) against the layer order', file=sys.stderr)
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
