#!/usr/bin/env python3
"""Completeness check of the hand-written cyclide-sys crate against the C header.

Fails (exit 1, listing the differences) unless
  - the CYC_API functions of cyclide.h and the `pub fn`s of the crate's
    extern "C" block are the same names with the same number of parameters;
  - the `typedef struct`s of cyclide.h (with a body, and the opaque handles)
    and the crate's `pub struct`s are the same names;
  - the integer #define constants (CYC_*) and enum members of cyclide.h and
    cyclide_errors.h are `pub const`s of the crate;
  - tests/layout.c prints every struct with a body and every constant, so the
    layout test (tests/layout.rs) compares all of them with the C compiler.

Usage: check_sys.py [INCLUDE_DIR [SYS_CRATE_DIR]]
  INCLUDE_DIR   the directory holding cyclide/cyclide.h (default: the
                source tree's capi/include)
  SYS_CRATE_DIR the cyclide-sys crate (default: next to this script)
Python 3 standard library only.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def strip_c_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def strip_rust_comments(text):
    return re.sub(r"//[^\n]*", " ", text)


def count_params(params):
    """Top-level comma-separated parameters (nested (), <>, [] skipped)."""
    params = params.strip()
    if params in ("", "void"):
        return 0
    depth, count = 0, 1
    for ch in params:
        if ch in "(<[":
            depth += 1
        elif ch in ")>]":
            depth -= 1
        elif ch == "," and depth == 0:
            count += 1
    if params.rstrip().endswith(","):  # trailing comma (rustfmt)
        count -= 1
    return count


def balanced_args(text, start):
    """The text between the '(' at text[start] and its matching ')'."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] == "(":
            depth += 1
        elif text[i] == ")":
            depth -= 1
            if depth == 0:
                return text[start + 1 : i]
    raise ValueError("unbalanced parentheses")


def header_items(include_dir):
    hpath = os.path.join(include_dir, "cyclide", "cyclide.h")
    epath = os.path.join(include_dir, "cyclide", "cyclide_errors.h")
    h = strip_c_comments(open(hpath, encoding="utf-8").read())
    e = strip_c_comments(open(epath, encoding="utf-8").read())
    h = re.sub(r"#define\s+CYC_API[^\n]*", " ", h)
    funcs = {}
    for m in re.finditer(r"\bCYC_API\b[^;(]*?\b(cyc_\w+)\s*\(", h):
        funcs[m.group(1)] = count_params(balanced_args(h, m.end() - 1))
    structs = set(re.findall(r"typedef\s+struct\s+(\w+)\s*\{", h))
    opaque = set(re.findall(r"typedef\s+struct\s+(\w+)\s+\1\s*;", h))
    consts = set()
    for m in re.finditer(r"^\s*#define\s+(CYC_\w+)\s+\(?-?\d", h, flags=re.M):
        consts.add(m.group(1))
    for src in (h, e):
        for body in re.findall(r"\benum\s+\w+\s*\{(.*?)\}", src, flags=re.S):
            for item in body.split(","):
                name = item.split("=")[0].strip()
                if name:
                    consts.add(name)
    return funcs, structs, opaque, consts


def crate_items(crate_dir):
    src = strip_rust_comments(
        open(os.path.join(crate_dir, "src", "lib.rs"), encoding="utf-8").read()
    )
    funcs = {}
    for block in re.finditer(r'extern\s+"C"\s*\{', src):
        # the extern block ends at the matching brace
        depth, i = 0, block.end() - 1
        while True:
            if src[i] == "{":
                depth += 1
            elif src[i] == "}":
                depth -= 1
                if depth == 0:
                    break
            i += 1
        body = src[block.end() : i]
        for m in re.finditer(r"\bpub\s+fn\s+(\w+)\s*\(", body):
            funcs[m.group(1)] = count_params(balanced_args(body, m.end() - 1))
    structs = set(re.findall(r"\bpub\s+struct\s+(\w+)", src))
    consts = set(re.findall(r"\bpub\s+const\s+(\w+)\s*:", src))
    return funcs, structs, consts


def layout_items(crate_dir):
    path = os.path.join(crate_dir, "tests", "layout.c")
    text = strip_c_comments(open(path, encoding="utf-8").read())
    return set(re.findall(r"^\s*S\((\w+)\);", text, flags=re.M)), set(
        re.findall(r"^\s*C\((\w+)\);", text, flags=re.M)
    )


def main(argv):
    include_dir = argv[1] if len(argv) > 1 else os.path.join(HERE, "..", "..", "capi", "include")
    crate_dir = argv[2] if len(argv) > 2 else os.path.join(HERE, "cyclide-sys")
    hf, hs, ho, hc = header_items(include_dir)
    rf, rs, rc = crate_items(crate_dir)
    ls, lc = layout_items(crate_dir)
    problems = []

    def diff(what, a_name, a, b_name, b):
        for n in sorted(set(a) - set(b)):
            problems.append("%s %s: in %s, missing in %s" % (what, n, a_name, b_name))

    diff("function", "cyclide.h", hf, "cyclide-sys", rf)
    diff("function", "cyclide-sys", rf, "cyclide.h", hf)
    for n in sorted(set(hf) & set(rf)):
        if hf[n] != rf[n]:
            problems.append(
                "function %s: %d parameters in cyclide.h, %d in cyclide-sys" % (n, hf[n], rf[n])
            )
    diff("struct", "cyclide.h", hs | ho, "cyclide-sys", rs)
    diff("struct", "cyclide-sys", rs, "cyclide.h", hs | ho)
    diff("constant", "cyclide.h", hc, "cyclide-sys", rc)
    diff("struct", "cyclide.h", hs, "tests/layout.c", ls)
    diff("struct", "tests/layout.c", ls, "cyclide.h", hs)
    diff("constant", "cyclide.h", hc, "tests/layout.c", lc)
    if problems:
        print("cyclide-sys is out of step with the header:")
        for p in problems:
            print("  " + p)
        return 1
    print(
        "cyclide-sys matches cyclide.h: %d functions, %d structs (%d opaque), %d constants"
        % (len(hf), len(hs) + len(ho), len(ho), len(hc))
    )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
