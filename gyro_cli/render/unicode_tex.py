"""Free text (a file's title, source and notes) as LaTeX text mode, its Unicode maths
typeset: ``ψ̇`` -> ``$\\dot{\\psi}$``, ``θ₀`` -> ``$\\theta_{0}$``, ``ω_z`` ->
``$\\omega_{z}$``, ``√(I m g l)`` -> ``$\\sqrt{\\text{I m g l}}$``, ``m r²`` -> ``m
$r^{2}$``, ``10⁻³`` -> ``10$^{-3}$``.

The text is cut into pieces, each text or maths; neighbouring maths pieces are joined
into one ``$...$`` (two in a row would read as ``$$``, display maths). A character
pdflatex cannot set becomes ``?``; a line break or control character never reaches
LaTeX as itself (the one place user strings meet LaTeX).
"""

from __future__ import annotations

import re
import unicodedata
from functools import lru_cache

__all__ = ["UNICODE_MATH", "UNICODE_TEXT", "text_tex"]

TEXT_ESCAPES = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&",
                "#": r"\#", "%": r"\%", "_": r"\_", "^": r"\textasciicircum{}",
                "~": r"\textasciitilde{}", "|": r"\textbar{}", "<": r"\textless{}",
                ">": r"\textgreater{}"}

_GREEK = {"α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "epsilon",
          "ϵ": "epsilon", "ζ": "zeta", "η": "eta", "θ": "theta", "ϑ": "vartheta",
          "ι": "iota", "κ": "kappa", "λ": "lambda", "μ": "mu", "µ": "mu", "ν": "nu",
          "ξ": "xi", "π": "pi", "ϖ": "varpi", "ρ": "rho", "ϱ": "varrho", "σ": "sigma",
          "ς": "varsigma", "τ": "tau", "υ": "upsilon", "φ": "phi", "ϕ": "phi",
          "χ": "chi", "ψ": "psi", "ω": "omega", "Γ": "Gamma", "Δ": "Delta",
          "Θ": "Theta", "Λ": "Lambda", "Ξ": "Xi", "Π": "Pi", "Σ": "Sigma",
          "Υ": "Upsilon", "Φ": "Phi", "Ψ": "Psi", "Ω": "Omega"}
_SIGNS = {"°": r"^{\circ}", "−": "-", "≥": r"\ge", "≤": r"\le", "≠": r"\ne", "±": r"\pm",
          "∓": r"\mp", "×": r"\times", "·": r"\cdot", "⋅": r"\cdot", "÷": r"\div",
          "≈": r"\approx", "∼": r"\sim", "≃": r"\simeq", "≡": r"\equiv", "∝": r"\propto",
          "→": r"\to", "←": r"\leftarrow", "↔": r"\leftrightarrow", "⇒": r"\Rightarrow",
          "≪": r"\ll", "≫": r"\gg", "∞": r"\infty", "∂": r"\partial", "∇": r"\nabla",
          "∫": r"\int", "∑": r"\sum", "∏": r"\prod", "′": "'", "″": "''", "⊥": r"\perp",
          "∥": r"\parallel", "ℓ": r"\ell", "ħ": r"\hbar", "∘": r"\circ", "√": r"\surd",
          "½": r"\tfrac{1}{2}", "¼": r"\tfrac{1}{4}", "¾": r"\tfrac{3}{4}",
          "⅓": r"\tfrac{1}{3}", "⅔": r"\tfrac{2}{3}"}
#: Unicode a problem file may hold, as LaTeX maths (pdflatex has no glyph for them in text)
UNICODE_MATH = {**{c: "\\" + name for c, name in _GREEK.items()}, **_SIGNS}
#: Unicode set in text mode
UNICODE_TEXT = {"–": "--", "—": "---", "‘": "`", "’": "'", "“": "``", "”": "''",
                "…": r"\dots{}", "\u00a0": "~", "\u2009": r"\,", "\u202f": r"\,",
                "ß": r"\ss{}", "æ": r"\ae{}", "Æ": r"\AE{}", "ø": r"\o{}", "Ø": r"\O{}",
                "å": r"\aa{}", "Å": r"\AA{}", "ł": r"\l{}", "Ł": r"\L{}", "œ": r"\oe{}"}

_SUB = dict(zip("₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑₒₓₕₖₗₘₙₚₛₜᵢⱼᵣᵤᵥ", "0123456789+-=()aeoxhklmnpstijruv"))
_SUP = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿⁱ", "0123456789+-=()ni"))
#: combining marks over a letter: maths accents
_MATH_ACCENTS = {"\u0307": "dot", "\u0308": "ddot", "\u0302": "hat", "\u0304": "bar",
                 "\u0303": "tilde", "\u20d7": "vec"}
#: combining marks over a Latin letter in a word: text accents (Poincaré, Gödel)
_TEXT_ACCENTS = {"\u0307": ".", "\u0301": "'", "\u0300": "`", "\u0302": "^", "\u0308": '"',
                 "\u0303": "~", "\u0304": "=", "\u0327": "c", "\u030c": "v", "\u0306": "u", "\u030a": "r",
                 "\u030b": "H", "\u0328": "k"}

# a maths symbol: a Greek letter, its accents, then subscripts (Unicode, or ``_`` and up
# to eight letters or digits) and superscripts. A Latin letter stays text, upright as the
# words around it (``m r²``); only its subscript (``I_G``) or superscript is maths.
_ACCENTS = "".join(_MATH_ACCENTS)
_SUBS, _SUPS = "".join(_SUB), "".join(_SUP)
_GREEK_CLASS = "".join(_GREEK)
_SYMBOL = re.compile(
    rf"(?P<base>[{_GREEK_CLASS}])(?P<accents>[{_ACCENTS}]*)"
    rf"(?:(?P<sub>[{_SUBS}]+)|_(?P<plain>[A-Za-z0-9]{{1,8}}(?![A-Za-z0-9_])|"
    rf"[{_GREEK_CLASS}](?!\w)))?"
    rf"(?P<sup>[{_SUPS}]+)?")
_TRAILING = re.compile(rf"[{_SUBS}]+|[{_SUPS}]+")
_LATIN_SUB = re.compile(rf"(?<![\w\\])[A-Za-z]_(?P<plain>[A-Za-z0-9]{{1,8}}(?![A-Za-z0-9_])|"
                        rf"[{_GREEK_CLASS}](?![\w]))")


# A run of printable ASCII that LaTeX sets as itself: taken whole, where each of its
# characters would be tried against every pattern in turn. Its last letter is left to
# them when something follows (``I_G``, a letter and a combining accent).
_PLAIN = re.compile(r"[^\x00-\x1f\x7f-\U0010ffff" + re.escape("".join(TEXT_ESCAPES)) + "]+")


@lru_cache(maxsize=4096)  # a handout sets the same sentences, titles and units again
def text_tex(text: str) -> str:
    """``text`` in LaTeX text mode, its Unicode maths as inline maths."""
    pieces: list[tuple[bool, str]] = []  # (is maths, LaTeX)
    text = unicodedata.normalize("NFC", text)  # ≠ stays one sign; ψ̇ has no composed form
    pos = 0
    while pos < len(text):
        plain = _PLAIN.match(text, pos)
        end = plain.end() if plain else pos
        if end < len(text) and end > pos and text[end - 1].isalpha():
            end -= 1
        if end > pos:
            pieces.append((False, text[pos:end]))
            pos = end
            continue
        pos = _next_piece(text, pos, pieces)
    return _joined(pieces)


def _next_piece(text: str, pos: int, pieces: list[tuple[bool, str]]) -> int:
    """Append the piece at ``pos`` to ``pieces``; where the next one starts."""
    c = text[pos]
    if c == "√":
        return _root(text, pos, pieces)
    symbol = _SYMBOL.match(text, pos)
    if symbol:
        pieces.append((True, _symbol_tex(symbol)))
        return symbol.end()
    latin = _LATIN_SUB.match(text, pos)
    if latin:  # I_G: the letter as text, its subscript as maths
        pieces += [(False, c), (True, "_{" + _subscript(latin.group("plain")) + "}")]
        return latin.end()
    trailing = _TRAILING.match(text, pos)
    if trailing:  # after a number or a word: 10⁻³, m²
        table = _SUB if trailing.group()[0] in _SUB else _SUP
        mark = "_" if table is _SUB else "^"
        pieces.append((True, f"{mark}{{{''.join(table[t] for t in trailing.group())}}}"))
        return trailing.end()
    accented = _accented(c + text[pos + 1:pos + 2])
    if accented:
        pieces.append((False, accented[0]))
        return pos + accented[1]
    pieces.append(_char(c))
    return pos + 1


def _accented(pair: str) -> tuple[str, int] | None:
    """A Latin letter with a text accent (é, or e and a combining accent) as LaTeX, and how
    many characters it took."""
    letters = unicodedata.normalize("NFD", pair[0])
    took = 1
    if len(letters) == 1 and len(pair) == 2:
        letters, took = pair, 2
    if len(letters) == 2 and letters[0].isascii() and letters[0].isalpha():
        accent = _TEXT_ACCENTS.get(letters[1])
        if accent:
            return f"\\{accent}{{{letters[0]}}}", took
    return None


def _symbol_tex(m: re.Match[str]) -> str:
    base = m.group("base")
    tex = UNICODE_MATH.get(base, base)
    for mark in m.group("accents"):
        tex = f"\\{_MATH_ACCENTS[mark]}{{{tex}}}"
    if m.group("sub"):
        tex += "_{" + "".join(_SUB[c] for c in m.group("sub")) + "}"
    elif m.group("plain"):
        tex += "_{" + _subscript(m.group("plain")) + "}"
    if m.group("sup"):
        tex += "^{" + "".join(_SUP[c] for c in m.group("sup")) + "}"
    return tex


def _subscript(plain: str) -> str:
    """One letter or a number in maths italic as the step printer sets them, a Greek
    letter as its command; a word upright."""
    if plain in UNICODE_MATH:
        return UNICODE_MATH[plain]
    return plain if len(plain) == 1 or plain.isdigit() else f"\\mathrm{{{plain}}}"


def _root(text: str, pos: int, pieces: list[tuple[bool, str]]) -> int:
    """``√(...)`` or ``√x``: the radicand under ``\\sqrt``, set as the text around it."""
    start = pos + 1
    if start < len(text) and text[start] == "(":
        depth, end = 0, start
        while end < len(text):
            depth += {"(": 1, ")": -1}.get(text[end], 0)
            if depth == 0:
                break
            end += 1
        if depth == 0:
            pieces.append((True, f"\\sqrt{{\\text{{{text_tex(text[start + 1:end])}}}}}"))
            return end + 1
    operand = re.match(r"[0-9.]+|\w[\u0300-\u036f]*", text[start:])
    if operand:
        pieces.append((True, f"\\sqrt{{\\text{{{text_tex(operand.group())}}}}}"))
        return start + operand.end()
    pieces.append((True, r"\surd"))
    return start


def _char(c: str) -> tuple[bool, str]:
    if c in "\n\r\t\f\v":
        return False, " "
    if ord(c) < 32 or ord(c) == 127:
        return False, "?"
    if c in TEXT_ESCAPES:
        return False, TEXT_ESCAPES[c]
    if c in UNICODE_MATH:
        return True, UNICODE_MATH[c]
    if c in UNICODE_TEXT:
        return False, UNICODE_TEXT[c]
    if ord(c) > 127:
        return False, "?"
    return False, c


def _joined(pieces: list[tuple[bool, str]]) -> str:
    """Text pieces as they are; each run of maths pieces as one ``$...$``."""
    out: list[str] = []
    run: list[str] = []
    for is_math, tex in pieces:
        if is_math:
            # a command word (\theta) must not run into a following letter
            if run and re.search(r"\\[A-Za-z]+$", run[-1]) and tex[:1].isalpha():
                run.append(" ")
            run.append(tex)
            continue
        if run:
            out.append("$" + "".join(run) + "$")
            run = []
        out.append(tex)
    if run:
        out.append("$" + "".join(run) + "$")
    return "".join(out)
