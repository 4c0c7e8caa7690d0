#!/usr/bin/env python3
"""Fails when a C++ function body under host/ (or the paths given) is longer than the limit (default 80 lines).

A heuristic reader, not a compiler: comments, strings and preprocessor lines are blanked, then every `{` that
follows a `)` (optionally with const/noexcept/override/a trailing return type/a member-initializer list) at
namespace or class scope opens a function; lambdas inside it count towards it. Lines = closing line - opening
line + 1 of the whole definition's body.
Usage: tools/check_function_length.py [--max N] [--list] [PATH ...]
"""
import argparse
import pathlib
import re
import sys

SOURCE_SUFFIXES = {".cpp", ".h", ".hpp", ".cc"}
SCOPE_KEYWORDS = re.compile(r"\b(namespace|class|struct|union|enum)\b[^;{}()]*$")
CONTROL = re.compile(r"\b(if|for|while|switch|catch|do|else)\s*$")


def blank_comments_and_strings(text):
    """Replaces comments, string and char literals and preprocessor lines by spaces, keeping newlines."""
    out = []
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c == "#":
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        if c in " \t":
            out.append(c)
            i += 1
            continue
        at_line_start = c == "\n"
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                out.append(" ")
                i += 1
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(")" + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(" " * (j + 1 - i))
            i = j + 1
        else:
            out.append(c)
            i += 1
    return "".join(out)


def opens_function(prefix):
    """True when the text before a `{` (since the last ; { or }) ends like a function's head."""
    head = prefix.strip()
    if not head or SCOPE_KEYWORDS.search(head) or CONTROL.search(head) or head.endswith("="):
        return False
    if re.search(r"\)\s*(const|noexcept|override|final|mutable|\s)*(->\s*[\w:<>,\s\*&]+)?$", head):
        return not CONTROL.search(head[: head.find("(")]) if "(" in head else True
    # A constructor with a member-initializer list: `X::X(args) : a_(b), c_{d}` ends in ) or }.
    return bool(re.search(r"\)\s*:\s*[\w:]+\s*[({]", head))


def long_functions(path, limit):
    text = blank_comments_and_strings(path.read_text(errors="replace"))
    findings, stack, start = [], [], 0
    for i, c in enumerate(text):
        if c == "{":
            inside_function = any(kind == "function" for kind, _, _ in stack)
            kind = "block"
            if not inside_function and opens_function(text[start:i]):
                kind = "function"
            stack.append((kind, i, start))
            start = i + 1
        elif c == "}":
            if stack:
                kind, open_at, head_at = stack.pop()
                if kind == "function":
                    first = text.count("\n", 0, open_at) + 1
                    last = text.count("\n", 0, i) + 1
                    if last - first + 1 > limit:
                        name = re.findall(r"([~\w:]+)\s*\(", text[head_at:open_at])
                        findings.append((first, last - first + 1, name[0] if name else "?"))
            start = i + 1
        elif c == ";":
            start = i + 1
    return findings


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max", type=int, default=80)
    parser.add_argument("paths", nargs="*", default=["host"])
    args = parser.parse_args()
    files = []
    for p in map(pathlib.Path, args.paths):
        files += sorted(f for f in p.rglob("*") if f.suffix in SOURCE_SUFFIXES) if p.is_dir() else [p]
    count = 0
    for f in files:
        for line, length, name in long_functions(f, args.max):
            print(f"{f}:{line}: {name} is {length} lines (limit {args.max})")
            count += 1
    if count:
        print(f"check_function_length: {count} function(s) over {args.max} lines", file=sys.stderr)
    return 1 if count else 0


if __name__ == "__main__":
    sys.exit(main())
