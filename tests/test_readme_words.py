"""The spellings page lists every spelling and word the kinds accept (issue 23): each
word alias a kind declares (Param.words) is named on docs/spellings.md, where the
README's words section moved (issue 39)."""

from pathlib import Path

from gyro_cli import kinds as registry

PAGE = (Path(__file__).resolve().parent.parent / "docs" / "spellings.md").read_text()
SECTION = PAGE.split("# Spellings and words gyro reads", 1)[1].split("\n## ", 1)[0]


def _flat(text: str) -> str:
    """Lower case, words only: underscores, hyphens, backticks and commas are spaces."""
    import re

    return " ".join(re.sub(r"[^a-z0-9]+", " ", text.lower()).split())


def test_every_declared_word_is_on_the_spellings_page():
    missing = []
    section = _flat(SECTION)
    for name in registry.names():
        for param in registry.get(name).params:
            for spelling, choice in getattr(param, "words", ()):
                for word in (spelling, choice):
                    # a sense and a viewpoint ("clockwise_from_aft") are listed as their
                    # parts: each of its words must be there
                    parts = [_flat(word)] if "_from_" not in word else _flat(word).split()
                    if any(f" {part} " not in f" {section} " for part in parts) or \
                            "_from_" not in word and _flat(word) not in section:
                        missing.append(f"{name}.{param.name}: {word}")
    assert missing == []
