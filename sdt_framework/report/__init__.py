"""Reports: the paper's tables and figures from a results folder."""
