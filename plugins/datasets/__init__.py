"""Built-in datasets plugins, registered through the sdt_framework entry-point group."""
