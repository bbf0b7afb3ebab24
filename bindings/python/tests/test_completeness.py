"""The binding against cyclide.h: every CYC_API function, which ones the
binding declares, and that each declared one still exists with the same
number and kinds of parameters and return type; the structs' fields (names,
array sizes, types) and the status numbers of cyclide_errors.h.

The header is CYCLIDE_HEADER, else the source tree's
capi/include/cyclide/cyclide.h, else the one installed next to the library.
Set CYCLIDE_COVERAGE_TABLE=1 to print the whole table.
"""

import ctypes
import os
import re
import sys
import unittest

import cyclide
from cyclide import _lib
from cyclide.errors import STATUS

HERE = os.path.dirname(os.path.abspath(__file__))


def header_path(name="cyclide.h"):
    env = os.environ.get("CYCLIDE_HEADER")
    candidates = []
    if env:
        candidates.append(os.path.join(os.path.dirname(env), name))
    candidates.append(os.path.join(HERE, "..", "..", "..", "capi", "include", "cyclide", name))
    libdir = os.path.dirname(os.path.realpath(_lib.lib_path))
    candidates += [os.path.join(libdir, "..", "include", "cyclide", name),
                   os.path.join(libdir, "..", "..", "include", "cyclide", name)]
    for c in candidates:
        if os.path.exists(c):
            return os.path.normpath(c)
    raise unittest.SkipTest("%s not found (set CYCLIDE_HEADER)" % name)


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def split_top(s, sep=","):
    parts, depth, cur = [], 0, []
    for ch in s:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch == sep and depth == 0:
            parts.append("".join(cur))
            cur = []
        else:
            cur.append(ch)
    if "".join(cur).strip():
        parts.append("".join(cur))
    return [p.strip() for p in parts]


def parse_functions(text):
    """name -> (return kind, [parameter kinds]) of every CYC_API function."""
    text = strip_comments(text)
    out = {}
    for m in re.finditer(r"CYC_API\s+([^;(]*?)\b(cyc_\w+)\s*\(", text):
        ret, name = m.group(1), m.group(2)
        i, depth = m.end(), 1
        while depth:
            depth += {"(": 1, ")": -1}.get(text[i], 0)
            i += 1
        params = text[m.end():i - 1].strip()
        plist = [] if params in ("", "void") else split_top(params)
        out[name] = (c_kind(ret), [c_kind(p) for p in plist])
    return out


def c_kind(decl):
    """'ptr', 'double', 'int', 'size_t', 'float', 'void' or 'struct:NAME'."""
    d = decl.strip()
    if "*" in d or "[" in d or "cyc_error_handler" in d:
        return "ptr"
    words = [w for w in re.findall(r"[A-Za-z_]\w*", d) if w not in ("const", "struct", "enum")]
    base = words[0] if words else "void"
    if base in ("double", "int", "size_t", "float", "void"):
        return base
    return "struct:" + base


def ctypes_kind(t):
    if t is None:
        return "void"
    if t is ctypes.c_size_t:
        return "size_t"
    if t is ctypes.c_double:
        return "double"
    if t is ctypes.c_int:
        return "int"
    if t is ctypes.c_float:
        return "float"
    if t in (ctypes.c_void_p, ctypes.c_char_p) or issubclass(t, (ctypes._Pointer,
                                                                 ctypes._CFuncPtr)):
        return "ptr"
    if issubclass(t, ctypes.Structure):
        return "struct:" + t.__name__
    return "unknown:" + repr(t)


def parse_defines(text):
    vals = {}
    for m in re.finditer(r"^\s*#define\s+(CYC_\w+)\s+([^\n]+)$", text, flags=re.M):
        expr = strip_comments(m.group(2)).strip()
        try:
            vals[m.group(1)] = int(eval(expr, {"__builtins__": {}}, dict(vals)))
        except Exception:
            pass
    return vals


def parse_structs(text):
    """name -> [(field, dims, base)] of every `typedef struct NAME {...} NAME;`."""
    defines = parse_defines(text)
    text = strip_comments(text)
    out = {}
    for m in re.finditer(r"typedef\s+struct\s+(cyc_\w+)\s*\{(.*?)\}\s*(cyc_\w+)\s*;", text,
                         flags=re.S):
        fields = []
        for decl in m.group(2).split(";"):
            decl = " ".join(decl.split())
            if not decl:
                continue
            fp = re.match(r".*\(\s*\*\s*(\w+)\s*\)\s*\(", decl)
            if fp:  # function pointer
                fields.append((fp.group(1), (), "ptr"))
                continue
            first = re.match(r"((?:const\s+)?[A-Za-z_]\w*(?:\s+[A-Za-z_]\w*)*?\s*\**)\s*"
                             r"([A-Za-z_]\w*.*)$", decl)
            base_t, rest = first.group(1), first.group(2)
            for d in split_top(rest):
                ptr = d.startswith("*") or "*" in base_t
                d = d.lstrip("* ")
                name = re.match(r"(\w+)", d).group(1)
                dims = tuple(int(eval(x, {"__builtins__": {}}, defines))
                             for x in re.findall(r"\[([^\]]*)\]", d))
                fields.append((name, dims, "ptr" if ptr else c_kind(base_t)))
        out[m.group(1)] = fields
    return out


def ctypes_fields(cls):
    out = []
    for name, t in cls._fields_:
        dims = []
        while isinstance(t, type) and issubclass(t, ctypes.Array):
            dims.append(t._length_)
            t = t._type_
        out.append((name, tuple(dims), ctypes_kind(t)))
    return out


def compare_functions(header):
    """Differences between the binding's FUNCTIONS and the parsed header."""
    problems = []
    for name, (restype, argtypes) in sorted(_lib.FUNCTIONS.items()):
        if name not in header:
            problems.append("%s: declared by the binding, not in cyclide.h" % name)
            continue
        ret, params = header[name]
        if len(params) != len(argtypes):
            problems.append("%s: %d parameters in cyclide.h, %d in the binding"
                            % (name, len(params), len(argtypes)))
            continue
        mine = [ctypes_kind(t) for t in argtypes]
        if mine != params:
            problems.append("%s: parameter kinds %s in cyclide.h, %s in the binding"
                            % (name, params, mine))
        if ctypes_kind(restype) != ret:
            problems.append("%s: returns %s in cyclide.h, %s in the binding"
                            % (name, ret, ctypes_kind(restype)))
    return problems


class Completeness(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(header_path(), encoding="utf-8") as f:
            cls.text = f.read()
        cls.header = parse_functions(cls.text)

    def test_parser_sees_the_header(self):
        n_api = len(re.findall(r"^(?!#).*\bCYC_API\b", strip_comments(self.text), re.M))
        self.assertEqual(len(self.header), n_api)
        self.assertEqual(self.header["cyc_surface_eval"][1],
                         ["ptr", "ptr", "double", "double", "ptr", "ptr", "ptr", "ptr"])
        self.assertEqual(self.header["cyc_version_number"], ("int", []))

    def test_table(self):
        declared = set(_lib.FUNCTIONS)
        rows = sorted(self.header)
        covered = [n for n in rows if n in declared]
        table = ["%-50s %s" % (n, "declared" if n in declared else "-") for n in rows]
        summary = ("python binding: %d of %d CYC_API functions declared (%.0f%%)"
                   % (len(covered), len(rows), 100.0 * len(covered) / len(rows)))
        if os.environ.get("CYCLIDE_COVERAGE_TABLE"):
            print("\n".join(table))
        print("\n" + summary, file=sys.stderr)
        self.assertGreaterEqual(len(covered), 75)  # a floor against silent loss

    def test_declared_functions_match_the_header(self):
        self.assertEqual(compare_functions(self.header), [])

    def test_the_check_catches_drift(self):
        # A parameter dropped, a function renamed, a return or parameter type
        # changed in the parsed header: each is reported.
        h = dict(self.header)
        ret, params = h["cyc_surface_domain"]
        h["cyc_surface_domain"] = (ret, params[:-1])
        h["cyc_surface_kind2"] = h.pop("cyc_surface_kind")
        h["cyc_curve_degree"] = ("size_t", h["cyc_curve_degree"][1])
        ret, params = h["cyc_surface_parameter_of"]
        h["cyc_surface_parameter_of"] = (ret, params[:2] + ["int"] + params[3:])
        problems = compare_functions(h)
        for name in ("cyc_surface_domain", "cyc_surface_kind", "cyc_curve_degree",
                     "cyc_surface_parameter_of"):
            self.assertTrue(any(p.startswith(name + ":") for p in problems), (name, problems))
        self.assertEqual(len(problems), 4, problems)

    def test_structs_match_the_header(self):
        structs = parse_structs(self.text)
        problems = []
        for name, cls in sorted(_lib.STRUCTS.items()):
            if name not in structs:
                problems.append("%s: not a struct of cyclide.h" % name)
            elif structs[name] != ctypes_fields(cls):
                problems.append("%s: cyclide.h %s, binding %s"
                                % (name, structs[name], ctypes_fields(cls)))
        self.assertEqual(problems, [])

    def test_status_codes_match_cyclide_errors_h(self):
        with open(header_path("cyclide_errors.h"), encoding="utf-8") as f:
            text = strip_comments(f.read())
        codes = {m.group(1): int(m.group(2))
                 for m in re.finditer(r"\b(CYC_\w+)\s*=\s*(\d+)", text)}
        self.assertEqual(codes, STATUS)
        for name, value in codes.items():
            self.assertEqual(cyclide.status_name(value), name)

    def test_loaded_library_matches(self):
        version, number, abi = cyclide.version()
        self.assertEqual(abi, cyclide.ABI_VERSION)
        m = re.search(r'#define CYC_ABI_VERSION (\d+)', self.text + self._version_h())
        if m:
            self.assertEqual(int(m.group(1)), abi)

    def _version_h(self):
        for cand in (os.path.join(os.path.dirname(os.path.realpath(_lib.lib_path)), "..",
                                  "include", "cyclide", "cyclide_version.h"),):
            if os.path.exists(cand):
                with open(cand, encoding="utf-8") as f:
                    return f.read()
        return ""


if __name__ == "__main__":
    unittest.main()
