"""The IDE's project services that are neither HTTP nor storage: which file names a project may
hold, what its files compile to (the block tree and diagnostics), zip archives of a project, and
the example projects imported on first start."""
