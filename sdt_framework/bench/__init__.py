"""The benchmark orchestrator: scenarios, runs, results (SPEC sections 5-7)."""
