"""`gyro kinds`: every kind with its keys and answers, in columns that never run together."""

from __future__ import annotations


def _rows(rows: list[tuple[str, str, str]]) -> list[str]:
    """Three columns, each as wide as its longest entry plus two spaces."""
    if not rows:
        return []
    w0 = max(len(r[0]) for r in rows) + 2
    w1 = max(len(r[1]) for r in rows) + 2
    return [f"    {a:<{w0}}{b:<{w1}}{c}".rstrip() for a, b, c in rows]


def kind_text(kind, body_params) -> str:
    """One kind: its summary, given keys (with defaults) and answers."""
    lines = [f"{kind.name}: {kind.summary}  ({kind.chapter})", "  given:"]
    from ..core.alternatives import alternatives_of

    params = {p.name: p for p in kind.params}
    lines += _rows([(p.name, p.dimension, p.doc + (f" [default {p.default}]" if p.default else ""))
                    for p in kind.params] +
                   [(a.key, params[a.target].dimension, f"instead of {a.target}: {a.reading}")
                    for a in alternatives_of(params).values()])  # as books state them
    if kind.uses_body:
        lines.append(f"    body keys: {', '.join(p.name for p in body_params)}")
    lines.append("  answers:")
    lines += _rows([(a.name, a.dimension or "word", a.doc) for a in kind.answers])
    return "\n".join(lines) + "\n"


def kinds_text(registry, body_params) -> str:
    """Every kind."""
    return "\n".join(kind_text(registry.get(name), body_params) for name in registry.names())
