"""Render: results in, text, JSON, Markdown, LaTeX, JUnit and pictures out.
May import checking and below."""
