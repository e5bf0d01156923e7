from nasaq.cli import main

raise SystemExit(main())
