"""Command-line options shared by the benchmark scripts. Importing it
makes a script print its docstring (its usage) and exit on --help or -h."""
import sys


def _print_usage_if_asked():
    if "--help" in sys.argv[1:] or "-h" in sys.argv[1:]:
        main = sys.modules.get("__main__")
        print(((main.__doc__ if main else None) or "").strip())
        sys.exit(0)


_print_usage_if_asked()


def take_option(arguments, name, convert=str, default=None):
    """Removes '--name value' from the list arguments and returns
    convert(value), or default if the option is not there; exits with a
    message naming the option if its value is missing or invalid."""
    if name not in arguments:
        return default
    k = arguments.index(name)
    kind = {"int": "an integer", "float": "a number"}.get(convert.__name__,
                                                          "a value")
    if k + 1 >= len(arguments):
        sys.exit("%s needs %s" % (name, kind))
    try:
        value = convert(arguments[k + 1])
    except ValueError:
        sys.exit("%s needs %s; got '%s'" % (name, kind, arguments[k + 1]))
    del arguments[k:k + 2]
    return value
