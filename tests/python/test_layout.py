"""The package's declarations of the C API against the installed headers:
every struct field's offset and every struct's size as the compiler lays
them out, every enum value, and the ABI version and release the package is
written for. A public struct that changes under the package fails here
(with the ABI version, which must then move: tests/install/test_abi.sh)."""

import os
import pathlib
import re
import subprocess

import candela
from candela import _capi

PREFIX = pathlib.Path(os.environ["CANDELA_TEST_PREFIX"])


def compiled_layout(tmp_path):
    """{name: value} printed by a C program compiled against the installed
    headers: 'struct.field' offsets, 'struct' sizes, enum constants."""
    lines = ["#include <stddef.h>", "#include <stdio.h>", "#include <candela/candela.h>", "int main(void)", "{"]
    for struct in _capi.STRUCTS:
        name = struct.__name__
        lines.append(f'    printf("{name} %zu\\n", sizeof({name}));')
        for field, *_ in struct._fields_:
            lines.append(f'    printf("{name}.{field} %zu\\n", offsetof({name}, {field}));')
    for constant in _capi.CONSTANTS:
        lines.append(f'    printf("{constant} %d\\n", (int)({constant}));')
    lines += ["    return 0;", "}"]
    source = tmp_path / "layout.c"
    source.write_text("\n".join(lines) + "\n")
    program = tmp_path / "layout"
    subprocess.run(
        [os.environ["CC"], "-std=c11", "-Wall", "-Werror", f"-I{PREFIX / 'include'}", f"-I{PREFIX / 'include' / 'candela'}", str(source), "-o", str(program)],
        check=True,
    )
    out = subprocess.run([str(program)], check=True, capture_output=True, text=True).stdout
    return {name: int(value) for name, value in (line.split() for line in out.splitlines())}


def test_structs_and_enums_match_the_headers(tmp_path):
    c = compiled_layout(tmp_path)
    python = {}
    for struct in _capi.STRUCTS:
        python[struct.__name__] = _capi.ctypes.sizeof(struct)
        for field, *_ in struct._fields_:
            python[f"{struct.__name__}.{field}"] = getattr(struct, field).offset
    python.update(_capi.CONSTANTS)
    assert python == c


def test_every_struct_declares_every_field_of_the_header():
    """The size check above catches a field missing at the end; this names
    any field of the installed header that the package does not declare."""
    headers = (PREFIX / "include" / "candela").rglob("*.h")
    text = "\n".join(h.read_text() for h in headers)
    for struct in _capi.STRUCTS:
        name = struct.__name__
        body = re.search(r"typedef struct %s \{(.*?)\} %s;" % (name, name), text, re.S)
        assert body, name
        declared = {field for field, *_ in struct._fields_}
        # the fields of the C body: the names before ';' or ',' or '[' of each declaration
        code = re.sub(r"/\*.*?\*/", "", body.group(1), flags=re.S)
        names = set()
        for decl in code.split(";"):
            decl = decl.strip()
            if not decl:
                continue
            if "(" in decl:  # a function pointer: (*name)
                names.add(re.search(r"\(\*\s*(\w+)\)", decl).group(1))
                continue
            head, *rest = decl.split(",")
            names.add(re.findall(r"(\w+)\s*(?:\[[^\]]*\])?\s*$", head)[0])
            names.update(re.findall(r"^\s*\*?\s*(\w+)", r)[0] for r in rest)
        assert names == declared, name


def test_abi_and_release_are_the_build_s():
    assert candela.ABI_VERSION == int(os.environ["CANDELA_ABI_VERSION"])
    assert candela.__version__ == os.environ["CANDELA_PROJECT_VERSION"]
    pyproject = (pathlib.Path(os.environ["CANDELA_SOURCE_DIR"]) / "python" / "pyproject.toml").read_text()
    assert re.search(r'^version = "%s"$' % re.escape(os.environ["CANDELA_PROJECT_VERSION"]), pyproject, re.M)
