"""``python -m epicyclic``: the same as the ``epicyclic`` command."""

from epicyclic.cli.main import main

if __name__ == "__main__":
    main()
