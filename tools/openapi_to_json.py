#!/usr/bin/env python3
"""Prints api/openapi.yaml (or the YAML file given) as JSON: for the build, which compiles it
into the service as GET /openapi.json (api/CMakeLists.txt), and for the C++ contract tests.

Uses Debian's python3-yaml. PyYAML follows YAML 1.1, where `1e-12` (no dot) is a
string and `yes`/`no`/`on`/`off` are booleans; the spec is read as YAML 1.2 core
schema instead (what Redocly and code generators use), so the tests see the same
numbers and booleans as every other reader. Duplicate keys are an error: YAML
readers disagree on which one wins.

usage: openapi_to_json.py SPEC.yaml [OUT.json]
"""

import json
import math
import re
import sys

import yaml


class Yaml12Loader(yaml.SafeLoader):
    """SafeLoader with YAML 1.2 core-schema booleans and floats, rejecting duplicate keys."""


# Drop the YAML 1.1 resolvers for bool, int (0b.., 1_000, 1:20 sexagesimal) and float,
# then add the YAML 1.2 core ones, int before float.
_REPLACED = ('tag:yaml.org,2002:bool', 'tag:yaml.org,2002:int', 'tag:yaml.org,2002:float')
Yaml12Loader.yaml_implicit_resolvers = {
    first: [(tag, regexp) for tag, regexp in resolvers if tag not in _REPLACED]
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}
Yaml12Loader.add_implicit_resolver(
    'tag:yaml.org,2002:bool', re.compile(r'^(?:true|True|TRUE|false|False|FALSE)$'),
    list('tTfF'))
Yaml12Loader.add_implicit_resolver(
    'tag:yaml.org,2002:int', re.compile(r'^(?:[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+)$'),
    list('-+0123456789'))
Yaml12Loader.add_implicit_resolver(
    'tag:yaml.org,2002:float',
    re.compile(r'^(?:[-+]?(?:\.[0-9]+|[0-9]+(?:\.[0-9]*)?)(?:[eE][-+]?[0-9]+)?'
               r'|[-+]?\.(?:inf|Inf|INF)|\.(?:nan|NaN|NAN))$'),
    list('-+0123456789.'))


def construct_mapping(loader, node, deep=False):
    keys = set()
    for key_node, _ in node.value:
        key = loader.construct_object(key_node, deep=deep)
        if key in keys:
            raise yaml.constructor.ConstructorError(
                None, None, f'duplicate key {key!r}', key_node.start_mark)
        keys.add(key)
    return yaml.SafeLoader.construct_mapping(loader, node, deep=deep)


def construct_int(loader, node):
    # YAML 1.2: 017 is seventeen (YAML 1.1 read it as octal).
    text = loader.construct_scalar(node)
    if text.startswith('0o'):
        return int(text[2:], 8)
    if text.startswith('0x'):
        return int(text[2:], 16)
    return int(text, 10)


Yaml12Loader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, construct_mapping)
Yaml12Loader.add_constructor('tag:yaml.org,2002:int', construct_int)


def check_json_compatible(value, where='#'):
    """JSON has string keys only and no infinities or NaN."""
    if isinstance(value, dict):
        for key, member in value.items():
            if not isinstance(key, str):
                raise ValueError(f'{where}: key {key!r} is not a string (quote it)')
            check_json_compatible(member, f'{where}/{key}')
    elif isinstance(value, list):
        for i, member in enumerate(value):
            check_json_compatible(member, f'{where}/{i}')
    elif isinstance(value, float) and not math.isfinite(value):
        raise ValueError(f'{where}: {value} is not a JSON number')
    elif not isinstance(value, (str, int, float, bool, type(None))):
        raise ValueError(f'{where}: {type(value).__name__} is not a JSON value')


def main(argv):
    if len(argv) not in (2, 3):
        sys.stderr.write(__doc__)
        return 2
    with open(argv[1], encoding='utf-8') as f:
        spec = yaml.load(f, Loader=Yaml12Loader)
    check_json_compatible(spec)
    text = json.dumps(spec, ensure_ascii=False, indent=1, allow_nan=False) + '\n'
    if len(argv) == 3:
        with open(argv[2], 'w', encoding='utf-8') as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
