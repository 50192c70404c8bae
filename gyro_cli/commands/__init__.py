"""Commands: the work behind the click commands that is more than a call
(authoring templates and schemas, simulate). May import every layer below."""
