"""sdt-framework's built-in plugins (import name ``sdt_plugins``).

They are discovered through the ``sdt_framework`` entry-point group declared in
the project's pyproject.toml, exactly like a third-party plugin; the core never
imports them by name.
"""
