"""The docs' Python blocks run as pasted, and print what their comments say they print (:func:`run`).

A line ``print(...)  # OUTPUT`` states what it prints.  Where the comment's head is written as output (Python
literals, numbers, ``True``/``False``/``None``), the head is checked and the rest, after ``": "`` or ``" (words"``,
explains it: ``# [5.71839138]: sqrt(g/(3 r))``, ``# (2,)``; ``...`` stands for any text (``# [1.80083901...]``).
A comment of words is checked as it is (``# numeric``), or, in a page that writes notes there (the README:
``# which model, and why that one``), is a note.  A ``print`` in a loop states its lines in the comments that follow
the loop, one per call.  Every docs runner of the tests calls :func:`run`.
"""
from __future__ import annotations

import io
import re
import sys
import tokenize
import types

#: the tokens an output may be made of, beside numbers and strings
_OUTPUT_NAMES = {"True", "False", "None"}
_OUTPUT_OPS = set("()[]{},.:-+") | {"...", "..", "*"}


def head(comment: str) -> str:
    """What ``comment`` (without its ``#``) says is printed: the text before a top-level ``": "`` or
    ``" ("`` followed by a letter (an explanation)."""
    depth, quote = 0, None
    for i, c in enumerate(comment):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif depth == 0 and c == "(" and comment[i - 1:i] == " " and comment[i + 1:i + 2].isalpha():
            return comment[:i - 1]
        elif depth == 0 and comment.startswith(": ", i):
            return comment[:i]
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
    return comment


def is_output(text: str) -> bool:
    """Whether ``text`` is written as output (literals, numbers, ``...``), not as words."""
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(text).readline))
    except (tokenize.TokenError, IndentationError, SyntaxError):
        return False
    seen = False
    for tok in tokens:
        if tok.type in (tokenize.NEWLINE, tokenize.NL, tokenize.ENDMARKER):
            continue
        if not (tok.type in (tokenize.NUMBER, tokenize.STRING) or (tok.type == tokenize.NAME and tok.string in _OUTPUT_NAMES)
                or (tok.type == tokenize.OP and tok.string in _OUTPUT_OPS)):
            return False
        seen = True
    return seen


def claims(code: str, notes: bool = False) -> dict:
    """``{line number: [expected outputs]}`` of the block ``code``: a line ``print(...)  # OUTPUT`` expects
    ``OUTPUT`` at each call (its head, :func:`head`, where that is written as output; a comment of words is
    expected as it is, unless ``notes``: then it is a note, not checked); a ``print`` in a loop without a comment
    expects, call after call, the comment lines that follow the loop (``# 1.2 True``, one per call)."""
    out, lines = {}, code.splitlines()
    for tok in tokenize.generate_tokens(io.StringIO(code).readline):
        if tok.type == tokenize.COMMENT and tok.line.lstrip().startswith("print("):
            comment = tok.string[1:].strip()
            expected = head(comment).strip()
            if is_output(expected):
                out[tok.start[0]] = [expected]
            elif not notes:
                out[tok.start[0]] = [comment]
    loop_print = None
    for number, line in enumerate(lines, 1):
        if line.startswith("    ") and line.lstrip().startswith("print(") and "#" not in line:
            loop_print = number
        elif line.startswith("# ") and loop_print is not None and number > 1 \
                and (lines[number - 2].startswith("    ") or lines[number - 2].startswith("# ")):
            out.setdefault(loop_print, []).append(line[2:].strip())
        elif not line.startswith("    "):
            loop_print = None
    return out


def matches(expected: str, printed: str) -> bool:
    """Whether ``printed`` is ``expected``, where ``...`` in ``expected`` stands for any text."""
    pattern = ".*".join(re.escape(part) for part in expected.split("..."))
    return re.fullmatch(pattern, printed.strip(), flags=re.S) is not None


def _codes(code: types.CodeType) -> set:
    """``code`` and the code objects nested in it (the block's functions, comprehensions)."""
    out = {code}
    for const in code.co_consts:
        if isinstance(const, types.CodeType):
            out |= _codes(const)
    return out


def run(code: str, filename: str, namespace: dict | None = None, notes: bool = False) -> dict:
    """Run the block ``code`` (named ``filename`` in tracebacks) in ``namespace`` (a new one if None), with a
    ``print`` that checks what :func:`claims` finds (``notes``: comments of words are notes); AssertionError if a
    line prints something else, or a stated output is never printed.  Returns the namespace."""
    namespace = {} if namespace is None else namespace
    compiled = compile(code, filename, "exec")
    expected, own = claims(code, notes), _codes(compiled)
    calls = {line: 0 for line in expected}

    def checked_print(*args, **kwargs):
        frame = sys._getframe(1)
        line = frame.f_lineno if frame.f_code in own else None
        if line in expected and "file" not in kwargs:
            buffer = io.StringIO()
            print(*args, **kwargs, file=buffer)
            printed, wanted = buffer.getvalue(), expected[line]
            # one comment states every call's output; comment lines after a loop state one call's each
            said = wanted[0] if len(wanted) == 1 else (wanted[calls[line]] if calls[line] < len(wanted) else None)
            calls[line] += 1
            assert said is not None and matches(said, printed), (
                f"{filename}: the block's line {line} prints {printed.strip()!r}; its comment says {said!r}")
        print(*args, **kwargs)

    namespace["print"] = checked_print
    try:
        exec(compiled, namespace)  # noqa: S102 - the docs' own code
    finally:
        namespace.pop("print", None)
    short = {line: (calls[line], len(wanted)) for line, wanted in expected.items()
             if calls[line] == 0 or (len(wanted) > 1 and calls[line] != len(wanted))}
    assert not short, f"{filename}: lines that say what they print ran (times, outputs said): {short}"
    return namespace
