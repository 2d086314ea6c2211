from cook2ltl.cli import main

main()
