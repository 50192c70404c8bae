"""Write-ups: a solved problem as Markdown or LaTeX for an instructor's solution sheet.

`gyro solve --format markdown|latex`. The structured steps of the worked
answer (``work.Step``: symbol, formula, substitution, value, unit, ref, text)
are typeset through a small transliteration of the plain formulas:
``phidot`` -> ``\\dot{\\phi}``, ``theta`` -> ``\\theta``, ``omega_z`` ->
``\\omega_{z}``, ``sqrt(...)`` -> ``\\sqrt{...}``, ``^2`` -> ``^{2}``,
``3.869e-05`` -> ``3.869\\times10^{-5}``, a unit after a number in upright
``\\mathrm{...}``, and words in ``\\text{...}``. Only amsmath is needed (for
``\\text``); Markdown uses ``$...$`` and ``$$...$$`` (GitHub, Pandoc, Jupyter).
"""

from __future__ import annotations

import re

from ..solving.solve import Result
from ..core.work import num

GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa",
         "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau", "phi", "chi", "psi", "omega",
         "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega"}
FUNCTIONS = {"sin", "cos", "tan", "exp", "ln", "log", "arcsin", "arccos", "arctan", "sinh",
             "cosh", "tanh"}
UNITS = {"kg", "m", "s", "N", "rad", "rpm", "deg", "mm", "cm", "km", "in", "ft", "lb", "lbf",
         "oz", "ozf", "slug", "Hz", "min", "h", "J", "W", "revolution", "rev", "g", "lbm",
         "degree", "radian", "second", "minute", "meter", "metre", "newton", "kip", "mi", "yd"}
SHORT_WORDS = {"a", "an", "as", "at", "be", "by", "if", "in", "is", "it", "no", "of", "on", "or",
               "so", "to", "we", "up"}

_TOKEN = re.compile(r"""
    (?P<num>\d+(?:\.\d*)?(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?)
  | (?P<name>[A-Za-z][A-Za-z0-9_]*)
  | (?P<op>>=|<=|\+-|!=|[-+*/=<>^(),;:.!?'%&#$|\[\]{}~\\"@`])
  | (?P<space>\s+)
  | (?P<other>.)
""", re.X | re.S)

_TEXT_ESCAPES = {"\\": r"\textbackslash{}", "{": r"\{", "}": r"\}", "$": r"\$", "&": r"\&",
                 "#": r"\#", "%": r"\%", "_": r"\_", "^": r"\textasciicircum{}",
                 "~": r"\textasciitilde{}"}
_MATH_OPS = {">=": r"\ge ", "<=": r"\le ", "+-": r"\pm ", "!=": r"\ne ", "*": r"\cdot ",
             "%": r"\%", "&": r"\&", "#": r"\#", "$": r"\$", "{": r"\{", "}": r"\}",
             "~": r"\sim ", "\\": r"\backslash ", '"': "''", "@": r"\text{@}", "`": "'"}


# Unicode a problem file may hold, as LaTeX maths (pdflatex has no glyph for them in math).
UNICODE_MATH = {"θ": r"\theta", "φ": r"\phi", "ψ": r"\psi", "ω": r"\omega", "α": r"\alpha",
                "β": r"\beta", "γ": r"\gamma", "δ": r"\delta", "μ": r"\mu", "µ": r"\mu",
                "π": r"\pi", "ρ": r"\rho", "σ": r"\sigma", "τ": r"\tau", "Ω": r"\Omega",
                "Δ": r"\Delta", "°": r"^{\circ}", "≥": r"\ge", "≤": r"\le", "±": r"\pm",
                "×": r"\times", "·": r"\cdot", "−": "-", "≈": r"\approx", "→": r"\to"}


def text_escape(text: str) -> str:
    """Plain text safe in LaTeX (Greek and math signs as inline maths)."""
    return "".join(_TEXT_ESCAPES.get(c) or (f"${UNICODE_MATH[c]}$" if c in UNICODE_MATH else c)
                   for c in text)


_keys: frozenset[str] | None = None


def _FILE_KEYS() -> frozenset[str]:  # noqa: N802 - computed once, on first use
    global _keys
    if _keys is None:
        _keys = file_keys()
    return _keys


def _tokens(text: str) -> list[tuple[str, str]]:
    return [(m.lastgroup, m.group()) for m in _TOKEN.finditer(text)]


def file_keys() -> frozenset[str]:
    """Key and answer names of the problem format written with an underscore whose first
    part is a word, not a symbol (``bearing_forces``, ``cg_distance``; not ``theta_max``)."""
    from .. import kinds
    from ..core.body import BODY_PARAMS

    names = {p.name for p in BODY_PARAMS}
    for kind in map(kinds.get, kinds.names()):
        names |= {p.name for p in kind.params} | {a.name for a in kind.answers}
    return frozenset(n for n in names if "_" in n and not _is_symbol(n.partition("_")[0]))


def _is_symbol(base: str) -> bool:
    return base in GREEK or len(base) == 1 or bool(_dotted(base))


def is_word(name: str) -> bool:
    """An English word rather than a symbol (``because`` but not ``phidot`` or ``I_G``);
    a file key such as ``bearing_forces`` in prose counts as a word."""
    if "_" in name:
        return name in _FILE_KEYS()
    if name in GREEK or name in FUNCTIONS or name == "sqrt" or _dotted(name):
        return False
    if len(name) == 1:
        return False
    return name.isalpha()


def _dotted(name: str) -> tuple[str, str] | None:
    for suffix, accent in (("ddot", r"\ddot"), ("dot", r"\dot")):
        base = name[: -len(suffix)]
        if name.endswith(suffix) and (base in GREEK or len(base) == 1):
            return base, accent
    return None


def symbol_tex(name: str) -> str:
    """One symbol: ``phidot`` -> ``\\dot{\\phi}``, ``psidot_min`` -> ``\\dot{\\psi}_{\\mathrm{min}}``."""
    base, _, sub = name.partition("_")
    dotted = _dotted(base)
    if dotted:
        core = f"{dotted[1]}{{{symbol_tex(dotted[0])}}}"
    elif base in GREEK:
        core = f"\\{base}"
    elif base in FUNCTIONS:
        core = f"\\{base}"
    elif len(base) == 1:
        core = base
    else:
        core = f"\\mathrm{{{base}}}"
    if sub:
        inner = symbol_tex(sub) if (sub in GREEK or len(sub) == 1 or _dotted(sub)) \
            else f"\\mathrm{{{text_escape(sub)}}}"
        core += f"_{{{inner}}}"
    return core


def number_tex(text: str) -> str:
    """``3.869e-05`` -> ``3.869\\times10^{-5}``."""
    mantissa, _, exponent = text.lower().partition("e")
    if not exponent:
        return text
    return f"{mantissa}\\times10^{{{int(exponent)}}}"


def unit_tex(unit: str) -> str:
    """A unit in upright type: ``kg m^2`` -> ``\\mathrm{kg\\,m^{2}}``; ``deg`` -> ``^{\\circ}``."""
    unit = unit.strip().replace("*", " ")
    if unit in ("deg", "degree"):
        return "^{\\circ}"
    if not unit:
        return ""
    out = []
    for kind, tok in _tokens(unit):
        if kind == "space":
            out.append("\\,")
        elif kind == "num":
            out.append(tok)
        elif kind == "name":
            out.append(text_escape(tok))
        elif tok == "^":
            out.append("^")
        else:
            out.append(_MATH_OPS.get(tok, tok))
    body = re.sub(r"\^(-?\d+)", r"^{\1}", "".join(out))
    body = re.sub(r"\^\\,", "^", body)
    return f"\\,\\mathrm{{{body}}}"


def _is_unit_run(toks: list[tuple[str, str]], k: int) -> int:
    """Length of a unit expression starting at toks[k] (after a number), or 0."""
    j, last = k, k
    while j < len(toks):
        kind, tok = toks[j]
        if kind == "name" and tok in UNITS:
            j += 1
            while j + 1 < len(toks) and toks[j][1] == "^" and toks[j + 1][0] in ("num",):
                j += 2
            if j + 2 < len(toks) and toks[j][1] == "^" and toks[j + 1][1] == "-" \
                    and toks[j + 2][0] == "num":
                j += 3
            last = j
            if j < len(toks) and toks[j][1] in ("/", "*"):
                j += 1
                continue
            if j < len(toks) and toks[j][0] == "space":
                j += 1
                continue
            break
        break
    if last == k:
        return 0
    # "2 m g l": a unit followed by a symbol is not a unit but a product of symbols.
    rest = last
    while rest < len(toks) and toks[rest][0] == "space":
        rest += 1
    if rest < len(toks) and toks[rest][0] == "name" and toks[rest][1] not in UNITS \
            and toks[rest][1] not in FUNCTIONS and toks[rest][1] != "sqrt" \
            and not is_word(toks[rest][1]):
        return 0
    return last - k


def math(text: str, units: bool = True) -> str:
    """Plain formula text as LaTeX math (no delimiters)."""
    toks = _tokens(text)
    return _math(toks, units)


def _math(toks: list[tuple[str, str]], units: bool) -> str:
    out: list[str] = []
    k = 0
    after_unit = False
    while k < len(toks):
        kind, tok = toks[k]
        if kind == "space":
            nxt = toks[k + 1] if k + 1 < len(toks) else ("", "")
            prev = out[-1] if out else ""
            if prev.startswith("\\text{") or (nxt[0] == "name" and is_word(nxt[1])):
                out.append("\\ ")
            elif after_unit and nxt[0] == "num":
                out.append("\\cdot ")
            else:
                out.append(" ")
            k += 1
            continue
        if kind == "num":
            out.append(number_tex(tok))
            k += 1
            if units:
                j = k
                while j < len(toks) and toks[j][0] == "space":
                    j += 1
                n = _is_unit_run(toks, j)
                if n:
                    out.append(unit_tex("".join(t for _, t in toks[j:j + n])))
                    k = j + n
                    after_unit = True
                    continue
            after_unit = False
            continue
        after_unit = False
        if kind == "name":
            if tok == "sqrt" and k + 1 < len(toks) and toks[k + 1][1] == "(":
                end = _matching(toks, k + 1)
                if end is not None:
                    out.append(f"\\sqrt{{{_math(toks[k + 2:end], units)}}}")
                    k = end + 1
                    continue
            if is_word(tok) or (tok in SHORT_WORDS and len(tok) > 1):
                out.append(f"\\text{{{text_escape(tok)}}}")
            else:
                out.append(symbol_tex(tok))
            k += 1
            continue
        if tok == "^":
            nxt = toks[k + 1] if k + 1 < len(toks) else ("", "")
            if nxt[0] in ("num", "name"):
                out.append(f"^{{{_math([nxt], False)}}}")
                k += 2
                continue
            if nxt[1] == "-" and k + 2 < len(toks) and toks[k + 2][0] == "num":
                out.append(f"^{{-{toks[k + 2][1]}}}")
                k += 3
                continue
            if nxt[1] == "(":
                end = _matching(toks, k + 1)
                if end is not None:
                    out.append(f"^{{{_math(toks[k + 2:end], units)}}}")
                    k = end + 1
                    continue
            out.append(r"\hat{}")
            k += 1
            continue
        if kind == "op":
            out.append(_MATH_OPS.get(tok, tok))
        elif tok in UNICODE_MATH:
            out.append(UNICODE_MATH[tok] + " ")
        else:
            out.append(f"\\text{{{text_escape(tok)}}}")
        k += 1
    return re.sub(r"(\\ )+", r"\\ ", "".join(out)).strip()


def _matching(toks: list[tuple[str, str]], start: int) -> int | None:
    depth = 0
    for j in range(start, len(toks)):
        if toks[j][1] == "(":
            depth += 1
        elif toks[j][1] == ")":
            depth -= 1
            if depth == 0:
                return j
    return None


def mixed(text: str, inline: tuple[str, str], escape=lambda s: s) -> str:
    """Prose with the maths in it set inline: words as text, symbols and numbers as math."""
    toks = _tokens(text)
    classes = _classify(toks)
    runs: list[tuple[bool, list[tuple[str, str]]]] = []
    for tok, is_math in zip(toks, classes):
        if runs and runs[-1][0] == is_math:
            runs[-1][1].append(tok)
        else:
            runs.append((is_math, [tok]))
    out = []
    for is_math, part in runs:
        if is_math and any(k in ("num", "name") for k, _ in part):
            first, last = _first_nonspace(part), _last_nonspace(part)
            core = part[first:last + 1]
            # Unbalanced brackets at the ends belong to the sentence, not the maths.
            head = tail = ""
            while core and (core[-1][0] == "space" or core[-1][1] == "("
                            or (core[-1][1] == ")" and _depth(core) < 0)):
                tail = core.pop()[1] + tail
            while core and (core[0][0] == "space" or core[0][1] == ")"
                            or (core[0][1] == "(" and _depth(core) > 0)):
                head += core.pop(0)[1]
            if not core:
                out.append(escape(lead_text(part)))
                continue
            lead = "".join(t for _, t in part[:first])
            trail = "".join(t for _, t in part[last + 1:])
            out.append(f"{escape(lead + head)}{inline[0]}{_math(core, True)}{inline[1]}"
                       f"{escape(tail + trail)}")
        else:
            out.append(escape("".join(t for _, t in part)))
    return "".join(out)


def lead_text(part: list[tuple[str, str]]) -> str:
    return "".join(t for _, t in part)


def _depth(part: list[tuple[str, str]]) -> int:
    return sum(t == "(" for _, t in part) - sum(t == ")" for _, t in part)


def _classify(toks: list[tuple[str, str]]) -> list[bool]:
    """For each token of a prose line: is it maths?"""
    classes: list[bool] = []
    unit_left = 0
    previous: list[str] = []  # the last non-space tokens
    for k, (kind, tok) in enumerate(toks):
        if unit_left:
            unit_left -= 1
            classes.append(True)
        elif kind == "name":
            possessive = tok == "s" and previous[-1:] == ["'"] and k > 1 \
                and toks[k - 2][0] == "name"
            classes.append(not (is_word(tok) or tok in SHORT_WORDS or possessive))
        elif kind == "space":
            classes.append(classes[-1] if classes else False)
        elif kind == "num":
            # "Eq. 11.13" is a reference, not a number in the maths.
            is_ref = previous[-2:] in (["Eq", "."], ["Eqs", "."]) or \
                (previous[-1:] == ["-"] and classes and not classes[-1])
            classes.append(not is_ref)
            if not is_ref:
                j = k + 1
                while j < len(toks) and toks[j][0] == "space":
                    j += 1
                run = _is_unit_run(toks, j)
                if run:
                    unit_left = j - k - 1 + run
        else:
            classes.append(tok not in (",", ";", ":", ".", "?", "!", "'", '"'))
        if kind != "space":
            previous.append(tok)
    return classes


def _first_nonspace(part: list[tuple[str, str]]) -> int:
    return next(i for i, (k, _) in enumerate(part) if k != "space")


def _last_nonspace(part: list[tuple[str, str]]) -> int:
    return max(i for i, (k, _) in enumerate(part) if k != "space")


def is_prose(text: str) -> bool:
    """A line that is mostly words (set as a sentence) rather than an equation."""
    names = [t for k, t in _tokens(text) if k == "name"]
    words = [n for n in names if is_word(n) and n not in UNITS]
    return len(words) >= 2


def step_math(step) -> str:
    """``symbol = formula = substitution = value unit`` as LaTeX math."""
    parts = [math(step.symbol, units=False)]
    if step.formula:
        parts.append(math(step.formula, units=False))
    if step.substitution:
        parts.append(math(step.substitution))
    if step.value is not None:
        unit = {"kg*m^2": "kg m^2", "N*m": "N m"}.get(step.unit, step.unit)
        parts.append(number_tex(num(step.value)) + unit_tex(unit))
    return " = ".join(parts)


def _answer_parts(answer) -> list[str]:
    parts = []
    for i, value in enumerate(answer.values):
        if isinstance(value, str):
            body = f"\\text{{{text_escape(value)}}}"
        else:
            body = number_tex(num(value)) + unit_tex(answer.unit or "")
        label = answer.labels[i] if i < len(answer.labels) else ""
        parts.append((body, label))
    return parts


# ---- Markdown ---------------------------------------------------------------

def markdown(result: Result) -> str:
    """The worked answer as Markdown with $-delimited LaTeX maths."""
    problem, solution = result.problem, result.solution
    md = ("$", "$")
    lines = [f"## {problem.id}: {problem.title}".rstrip(": ") if problem.title
             else f"## {problem.id}", ""]
    meta = [f"Kind: `{problem.kind.name}`"] + ([f"Source: {problem.source}"] if problem.source
                                              else [])
    lines += ["*" + ". ".join(meta) + ".*", ""]
    for note in problem.notes:
        lines += [f"> {mixed(note, md)}", ""]
    lines += ["### Given", "", "| | as given | SI |", "|---|---|---|"]
    for g in solution.given:
        si = f"\\text{{{text_escape(g.si_value)}}}" if isinstance(g.si_value, str) \
            else number_tex(num(g.si_value)) + unit_tex(g.si_unit)
        note = f" ({g.note})" if g.note else ""
        lines.append(f"| ${symbol_tex(g.symbol)}$ | "
                     f"{_md_cell(g.text)}{_md_cell(note)} | ${si}$ |")
    for section in solution.sections:
        lines += ["", f"### {mixed(section.title, md)}", ""]
        lines += _md_steps(section.steps, md)
    if solution.checks:
        lines += ["", "### Check", ""]
        lines += _md_steps(solution.checks, md)
    lines += ["", "### Answer", ""]
    for name, answer in result.answers.items():
        parts = [f"${symbol_tex(answer.symbol)} = {body}$" + (f" ({label})" if label else "")
                 for body, label in _answer_parts(answer)]
        lines.append(f"- **{name}**: " + ", ".join(parts))
    if solution.warnings:
        lines += ["", "### Warnings", ""]
        lines += [f"- {w}" for w in solution.warnings]
    return _one_superscript("\n".join(lines) + "\n")


def _md_cell(text: str) -> str:
    return text.replace("|", "\\|")


def _md_steps(steps, md: tuple[str, str]) -> list[str]:
    out = []
    for step in steps:
        if step.symbol:
            tail = " ".join(f"\\text{{{text_escape(t)}}}" for t in
                            ([f"({step.ref})"] if step.ref else []) +
                            ([step.text] if step.text and is_prose(step.text) else []))
            extra = f"\\qquad {math(step.text)}" if step.text and not is_prose(step.text) else ""
            if tail:
                extra += f" \\qquad {tail}"
            out += [f"$$ {step_math(step)}{extra} $$", ""]
        elif is_prose(step.text):
            out += [mixed(step.text, md), ""]
        else:
            out += [f"$$ {math(step.text)} $$", ""]
    return out


# ---- LaTeX ------------------------------------------------------------------

def latex(result: Result) -> str:
    """The worked answer as a LaTeX fragment (needs amsmath) to paste into a solution sheet."""
    problem, solution = result.problem, result.solution
    inline = ("$", "$")
    title = f"{problem.id}: {problem.title}" if problem.title else problem.id
    lines = ["% gyro solve --format latex: paste into a document that loads amsmath",
             f"\\subsection*{{{text_escape(title)}}}"]
    meta = [f"Kind: {problem.kind.name}"] + ([f"Source: {problem.source}"] if problem.source
                                            else [])
    lines.append("\\textit{" + text_escape(". ".join(meta)) + ".}")
    for note in problem.notes:
        lines += ["", _latex_prose(note, inline)]
    lines += ["", "\\paragraph{Given.}", "", "\\begin{tabular}{lll}",
              "& as given & SI \\\\ \\hline"]
    for g in solution.given:
        si = f"\\text{{{text_escape(g.si_value)}}}" if isinstance(g.si_value, str) \
            else number_tex(num(g.si_value)) + unit_tex(g.si_unit)
        note = f" ({g.note})" if g.note else ""
        lines.append(f"${symbol_tex(g.symbol)}$ & {text_escape(g.text + note)} & ${si}$ \\\\")
    lines.append("\\end{tabular}")
    for section in solution.sections:
        lines += ["", f"\\paragraph{{{_latex_prose(section.title, inline)}.}}", ""]
        lines += _latex_steps(section.steps, inline)
    if solution.checks:
        lines += ["", "\\paragraph{Check.}", ""]
        lines += _latex_steps(solution.checks, inline)
    lines += ["", "\\paragraph{Answer.}", "", "\\begin{itemize}"]
    for name, answer in result.answers.items():
        parts = [f"${symbol_tex(answer.symbol)} = {body}$" + (f" ({text_escape(label)})"
                                                              if label else "")
                 for body, label in _answer_parts(answer)]
        lines.append(f"  \\item \\textbf{{{text_escape(name)}}}: " + ", ".join(parts))
    lines.append("\\end{itemize}")
    if solution.warnings:
        lines += ["", "\\paragraph{Warnings.}", "", "\\begin{itemize}"]
        lines += [f"  \\item {_latex_prose(w, inline)}" for w in solution.warnings]
        lines.append("\\end{itemize}")
    return _one_superscript("\n".join(lines) + "\n")


_DOUBLE_SUPERSCRIPT = re.compile(r"(\d[\d.]*\\times10\^\{-?\d+\})\^\{\\circ\}")


def _one_superscript(text: str) -> str:
    """Brace a number in powers of ten before a degree sign: ``a\\times10^{-5}^{\\circ}``
    is a double superscript, which TeX rejects; ``{a\\times10^{-5}}^{\\circ}`` is not."""
    return _DOUBLE_SUPERSCRIPT.sub(r"{\1}^{\\circ}", text)


def _latex_prose(text: str, inline: tuple[str, str]) -> str:
    """Prose for LaTeX: text escaped outside the maths, maths inline."""
    return mixed(text, inline, text_escape)


def _latex_steps(steps, inline: tuple[str, str]) -> list[str]:
    out = []
    for step in steps:
        if step.symbol:
            tail = []
            if step.ref:
                tail.append(f"\\text{{({text_escape(step.ref)})}}")
            if step.text:
                tail.append(math(step.text) if not is_prose(step.text)
                            else f"\\text{{{text_escape(step.text)}}}")
            extra = "".join(f" \\qquad {t}" for t in tail)
            out += [f"\\[ {step_math(step)}{extra} \\]"]
        elif is_prose(step.text):
            out += [_latex_prose(step.text, inline), ""]
        else:
            out += [f"\\[ {math(step.text)} \\]"]
    return out
