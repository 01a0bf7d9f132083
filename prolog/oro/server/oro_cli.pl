:- module(oro_cli,
          [ oro_cli_options/3,          % :Argv, -Positional, -Options
            oro_cli_settings_help/1,    % -Text
            oro_setting/2               % +Name, -Setting
          ]).
:- use_module(library(main), [argv_options/3, cli_parse_debug_options/2]).
:- use_module(library(settings)).
:- use_module(library(error)).
:- use_module(library(option)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(debug)).

:- meta_predicate
    oro_cli_options(:, -, -).

/** <module> The server's command line: options, settings, config file

Every setting of oro's modules (the `setting/4` declarations of the
modules named oro_*: limits, timeouts, defaults) is also an option:
`--max-connections=64` sets oro_server:max_connections,
`--time-limit=2` sets oro_query:time_limit (dashes or underscores; a
name two modules declare must be set in a config file).  A settings
file given with `--config=FILE` holds terms
`setting(Module:Name, Value).` (or `setting(Name, Value).`), as
save_settings/1 writes them; it is read before the other options,
which override it, wherever they stand on the command line.  A value
of the wrong type, an unknown setting or a file that does not exist is
an error: the server does not start.

`--debug=Topic` (repeatable) turns on SWI-Prolog's debug/3 topic
Topic, e.g. `--debug='oro(server)'` (cli_parse_debug_options/2).
*/

%!  oro_cli_options(:Argv, -Positional, -Options) is det.
%
%   Parse the command-line arguments Argv: the options the module M of
%   Argv declares with opt_type/3 (see argv_options/3) become Options;
%   `--config=File` is read and every other `--name=value` naming a
%   setting is set, in that order; `--debug=Topic` options are done.
%
%   @error existence_error(option, Name) for an option that is neither
%   declared nor a setting; errors of the settings file and values.

oro_cli_options(M:Argv, Positional, Options) :-
    must_be(list(atomic), Argv),
    partition(setting_argument(M), Argv, SettingArgs0, Rest),
    maplist(setting_argument(M), SettingArgs0, SettingArgs),
    argv_options(M:Rest, Positional, Options0),
    cli_parse_debug_options(Options0, Options),
    forall(member(config(File), Options),
           load_config(File)),
    forall(member(Setting=Text, SettingArgs),
           set_from_text(Setting, Text)).

%   setting_argument(+M, +Arg) is semidet: Arg is --name=text where
%   name is no option of M but names a setting.
%   setting_argument(+M, +Arg, -Setting=Text) is semidet: and names
%   Setting.

setting_argument(M, Arg) :-
    setting_argument(M, Arg, _).

setting_argument(M, Arg, Setting=Text) :-
    atom(Arg),
    atom_concat(--, Option, Arg),
    sub_atom(Option, Before, _, After, =),
    !,
    sub_atom(Option, 0, Before, _, Name0),
    sub_atom(Option, _, After, 0, Text),
    atomic_list_concat(Parts, -, Name0),
    atomic_list_concat(Parts, '_', Name),
    \+ M:opt_type(Name, _, _),
    oro_setting(Name, Setting).

set_from_text(Setting, Text) :-
    setting_property(Setting, type(Type)),
    (   catch(convert_setting_text(Type, Text, Value), _, fail),
        is_of_type(Type, Value)
    ->  set_setting(Setting, Value)
    ;   Setting = _:Name,
        domain_error(Type, Name=Text)
    ).

%!  oro_setting(+Name, -Setting) is semidet.
%
%   Setting (Module:Name) is the one setting called Name among the
%   modules oro_*, or Name itself if it is qualified and exists.  Fails
%   if there is none.
%
%   @error domain_error(unique_setting, Name) if several modules have
%   one.

oro_setting(Module:Name, Module:Name) :-
    !,
    current_setting(Module:Name).
oro_setting(Name, Setting) :-
    findall(Module:Name,
            ( current_setting(Module:Name),
              sub_atom(Module, 0, _, _, oro_)
            ),
            Settings),
    (   Settings = [Setting]
    ->  true
    ;   Settings = [_, _|_]
    ->  domain_error(unique_setting, Settings)
    ).

%   load_config(+File): set every setting File gives.

load_config(File) :-
    (   exists_file(File)
    ->  true
    ;   existence_error(file, File)
    ),
    setup_call_cleanup(open(File, read, In, [encoding(utf8)]),
                       config_terms(In, Terms),
                       close(In)),
    maplist(config_setting(File), Terms),
    debug(oro(server), 'Settings from ~w', [File]).

config_terms(In, Terms) :-
    read_term(In, Term, []),
    (   Term == end_of_file
    ->  Terms = []
    ;   Terms = [Term|More],
        config_terms(In, More)
    ).

config_setting(File, Term) :-
    (   Term = setting(Name, Value),
        oro_setting(Name, Setting)
    ->  set_setting(Setting, Value)
    ;   Term = setting(Name, _)
    ->  existence_error(setting, Name)
    ;   type_error(setting, Term)
    ),
    debug(oro(server), '~w: ~q', [File, Term]).

%!  oro_cli_settings_help(-Text) is det.
%
%   The options that set a setting, with their comment and default,
%   for `--help`.

oro_cli_settings_help(Text) :-
    findall(Name-Setting,
            ( current_setting(Module:Name),
              sub_atom(Module, 0, _, _, oro_),
              Setting = Module:Name
            ),
            Pairs0),
    keysort(Pairs0, Pairs),
    with_output_to(string(Text),
                   forall(member(Name-Setting, Pairs),
                          setting_help(Name, Setting))).

setting_help(Name, Setting) :-
    atomic_list_concat(Parts, '_', Name),
    atomic_list_concat(Parts, -, Option),
    setting_property(Setting, comment(Comment)),
    setting_property(Setting, default(Default)),
    format("  --~w=~q~n      ~w (~q)~n", [Option, Default, Comment, Setting]).
