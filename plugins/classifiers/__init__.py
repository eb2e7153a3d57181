"""Built-in classifiers plugins, registered through the sdt_framework entry-point group."""
