"""`python -m flywheel`: the same as the `flywheel` console script."""
if __name__ == "__main__":
    from flywheel.cli import main

    main()
