# bash completion for sphdeck: the subcommands and each one's options, read from sphdeck's own --help
# (so they never fall behind the program); other words complete as file names (decks, folders).
# Installed to share/bash-completion/completions/sphdeck; or: source completions/sphdeck.bash

# The names listed under "Subcommands:" in `sphdeck --help`.
_sphdeck_subcommands() {
    "$1" --help 2>/dev/null | awk '/^Subcommands:/ { on = 1; next } /^$/ { on = 0 } on { print $1 }'
}

# Every option name of `sphdeck COMMAND --help` ("  -o,--output-file TEXT  ..." gives -o and --output-file).
_sphdeck_options() {
    "$1" "$2" --help 2>/dev/null | awk '/^  -/ { n = split($1, names, ","); for (i = 1; i <= n; i++) print names[i] }'
}

_sphdeck() {
    local cur=${COMP_WORDS[COMP_CWORD]} program=${COMP_WORDS[0]} subcommand="" i
    for ((i = 1; i < COMP_CWORD; i++)); do
        if [[ ${COMP_WORDS[i]} != -* ]]; then
            subcommand=${COMP_WORDS[i]}
            break
        fi
    done
    if [[ -z $subcommand ]]; then
        if [[ $cur == -* ]]; then
            mapfile -t COMPREPLY < <(compgen -W "--help --version" -- "$cur")
        else
            mapfile -t COMPREPLY < <(compgen -W "$(_sphdeck_subcommands "$program")" -- "$cur")
        fi
    elif [[ $cur == -* ]]; then
        mapfile -t COMPREPLY < <(compgen -W "$(_sphdeck_options "$program" "$subcommand")" -- "$cur")
    else
        compopt -o filenames 2>/dev/null
        mapfile -t COMPREPLY < <(compgen -f -- "$cur")
    fi
}
complete -F _sphdeck sphdeck
