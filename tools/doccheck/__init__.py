"""Run the shell commands documented in README.md and docs/*.md and check what they print.

Every ``$ command`` line in a fenced block is run with bash in a sandbox folder
(``sdt`` of the running interpreter's environment first on PATH, the repository's
top-level folders linked in), and its exit status, the absence of a Python traceback
and its output (numbers masked, so noise in figures passes) are checked against the
lines the document shows below it. ``extract`` reads the documents, ``compare``
judges one output, ``sandbox`` runs one command, ``runner`` runs a document's
blocks in order; ``python -m tools.doccheck`` is the command-line entry.
"""
