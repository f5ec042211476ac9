from rbi.cli.app import main

main()
