"""Interactive lessons: the course on disk (``load``), its lint, the checks a learner's project
runs (``check``), quizzes (``quiz``) and progress stored per project (``progress``)."""
