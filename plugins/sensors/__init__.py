"""Built-in sensors plugins, registered through the sdt_framework entry-point group."""
