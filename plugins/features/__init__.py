"""Built-in features plugins, registered through the sdt_framework entry-point group."""
