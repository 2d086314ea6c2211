"""A test oracle for generated grammars: the GBNF subset they use, turned into a Python regex.

The generated grammars are not recursive, so every rule can be inlined. Supported: rules `name ::= …`,
"literals" (with llama.cpp's escapes: \\n \\r \\t \\" \\\\ \\xHH \\uHHHH \\UHHHHHHHH; any other is an error, as there),
[classes], (groups), alternation, and the ? * + {m,n} repetitions.
"""

from __future__ import annotations

import re

_TOKEN = re.compile(r'\s*("(?:[^"\\]|\\.)*"|\[(?:[^\]\\]|\\.)*\]|[a-z][a-z0-9-]*|[()|?*+]|\{\d+(?:,\d*)?\})')
_ESCAPES = {"n": "\n", "r": "\r", "t": "\t", '"': '"', "\\": "\\"}
_ESCAPE = re.compile(r"\\(x[0-9a-fA-F]{2}|u[0-9a-fA-F]{4}|U[0-9a-fA-F]{8}|.)", re.DOTALL)


def gbnf_regex(grammar: str) -> re.Pattern:
    rules = {}
    for line in grammar.splitlines():
        if line.strip():
            name, body = line.split("::=", 1)
            rules[name.strip()] = body
    return re.compile(_rule("root", rules, ()), re.DOTALL)


def accepts(grammar: str, text: str) -> bool:
    return gbnf_regex(grammar).fullmatch(text) is not None


def _rule(name: str, rules: dict[str, str], stack: tuple[str, ...]) -> str:
    if name in stack:
        raise ValueError(f"recursive rule {name}")
    tokens = [m.group(1) for m in _TOKEN.finditer(rules[name])]
    if "".join(tokens).replace(" ", "") != rules[name].replace(" ", "").strip():
        raise ValueError(f"unsupported syntax in rule {name}: {rules[name]}")
    return "(?:" + _alternation(tokens, rules, stack + (name,)) + ")"


def _alternation(tokens: list[str], rules, stack) -> str:
    out, depth = [""], 0
    for token in tokens:
        depth += token == "("
        depth -= token == ")"
        if token == "|" and depth == 0:
            out.append("")
        else:
            out[-1] += " " + token if out[-1] else token
    return "|".join(_sequence(_split(alt), rules, stack) for alt in out)


def _split(alternative: str) -> list[str]:
    return [m.group(1) for m in _TOKEN.finditer(alternative)]


def _sequence(tokens: list[str], rules, stack) -> str:
    pattern, index = "", 0
    while index < len(tokens):
        token = tokens[index]
        if token == "(":
            depth, end = 1, index + 1
            while depth:
                depth += tokens[end] == "("
                depth -= tokens[end] == ")"
                end += 1
            piece = "(?:" + _alternation(tokens[index + 1:end - 1], rules, stack) + ")"
            index = end
        else:
            piece = _atom(token, rules, stack)
            index += 1
        if index < len(tokens) and (tokens[index] in "?*+" or tokens[index].startswith("{")):
            piece += tokens[index]
            index += 1
        pattern += piece
    return pattern


def _atom(token: str, rules, stack) -> str:
    if token.startswith('"'):
        text = _ESCAPE.sub(_unescape, token[1:-1])
        return "(?:" + re.escape(text) + ")"
    if token.startswith("["):
        return token.replace("\\n", "\n")
    return _rule(token, rules, stack)


def _unescape(match: re.Match) -> str:
    escape = match.group(1)
    if escape[0] in "xuU" and len(escape) > 1:
        return chr(int(escape[1:], 16))
    if escape not in _ESCAPES:
        raise ValueError(f"unknown escape \\{escape} in a literal")
    return _ESCAPES[escape]
