/*  oro benchmark: the worst cost per byte of a request's parameters.

        swipl bench/bench_hostile.pl [--mb=1]

    Each row is a parameter of about MB megabytes built from one
    construct a hostile client may repeat (brackets, quotes, escapes,
    spaces, long names, many statements...), decoded and parsed as a
    method taking statements does it: oro_parse_collection/3 then
    oro_statements/3, within one parse budget (oro_parse_budget/1).
    Each runs in a thread of its own: CPU is the thread's CPU time,
    memory the stacks that thread had to allocate (statistics(stack)
    once done, before any trim), both per MB of the parameter.  The
    outcome is `ok` or the error the request gets.  The parse budget
    (oro_parse:inference_limit) is off while this runs; the column
    inferences/MB says how much of it each construct spends.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(settings)).
:- use_module(library(option)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(main), [argv_options/3]).
:- use_module(bench_common).
:- use_module(library(oro/server/oro_protocol)).

:- initialization(main, main).

opt_type(mb, mb, number).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(mb(MB), Options, 1),
    bench_machine,
    set_setting(oro_parse:inference_limit, 0),
    nl,
    format("~w~t~34|~w~t~12+~w~t~10+~w~t~12+~w~t~14+~w~n",
           [construct, 'bytes', 'CPU s/MB', 'stack MB/MB', 'inferences/MB',
            outcome]),
    Bytes is round(MB * 1048576),
    forall(construct(Name, Unit, Frame),
           row(Name, Unit, Frame, Bytes)),
    nl,
    format("~w~t~34|~w~t~12+~w~t~10+~w~n",
           ['request read (max_lines 5120)', bytes, 'CPU s/MB', outcome]),
    forall(request_construct(Name, Unit, Frame),
           read_row(Name, Unit, Frame, Bytes)).

%   request_construct(?Name, ?Unit, ?Frame): a whole request, Unit
%   repeated inside Frame, read by oro_protocol's reader with the
%   server's max_lines (max_params 4096 + 1024).

request_construct('empty lines',        "\n",  "add\n~sx\n#end#\n").
request_construct('leading empty lines', "\n", "~sadd\nx\n#end#\n").
request_construct('carriage returns',   "\r",  "add\n~sx\n#end#\n").
request_construct('short lines',        "a\n", "add\n~s#end#\n").

read_row(Name, Unit, Frame, Bytes) :-
    repeated(Unit, Bytes, Repeated),
    format(string(Request), Frame, [Repeated]),
    string_length(Request, Length),
    setup_call_cleanup(
        open_string(Request, In),
        ( oro_reader(In, Reader, [max_lines(5120)]),
          statistics(cputime, T0),
          oro_read_request(Reader, Read, _),
          statistics(cputime, T1)
        ),
        close(In)),
    (   Read = request(Method, _)
    ->  Outcome = Method
    ;   Outcome = Read
    ),
    MBs is Length / 1048576,
    format("~w~t~34|~D~t~12+~3f~t~10+~q~n",
           [Name, Length, (T1-T0)/MBs, Outcome]).

%   construct(?Name, ?Unit, ?Frame): Unit repeated inside Frame
%   (format/3 with one ~s).

construct('nested brackets [[[ ]]]',     nested("[", "]"), "[x p ~s]").
construct('nested braces {{{ }}}',       nested("{", "}"), "[x p ~s]").
construct('brackets, depth 1 [][]',      "[]",        "[x p ~s]").
construct('leading spaces',              " ",         "[\"~sx p o\"]").
construct('escaped quotes a\\"',         "a\\\"",     "[\"x p ~s\"]").
construct('backslashes \\\\',            "\\\\",      "[x p \"~s\"]").
construct('unicode escapes \\u0041',     "\\u0041",   "[x p \"~s\"]").
construct('single quotes \'',            "'",         "[x p ~s]").
construct('double quotes ""',            "\"\"",      "[x p o~s]").
construct('one long name',               "a",         "[x p ~s]").
construct('one long literal',            "a",         "[x p \"~s\"]").
construct('statements x p o,',           "x p o,",    "[~sx p o]").
construct('quoted statements "x p o",',  "\"x p o\",", "[~s\"x p o\"]").
construct('labelled statements',         "x rdfs:label \"a b\",", "[~sx p o]").
construct('empty elements ,',            ",",         "[~sx p o]").
construct('patterns ?x p ?y,',           "?x p ?y,",  "[~s?x p ?y]").

row(Name, Unit, Frame, Bytes) :-
    repeated(Unit, Bytes, Repeated),
    format(string(Param), Frame, [Repeated]),
    string_length(Param, Length),
    thread_self(Me),
    thread_create(( measure(Param, Cost),
                    thread_send_message(Me, bench_cost(Cost))
                  ), Thread, []),
    thread_join(Thread, Status),
    (   Status == true
    ->  thread_get_message(bench_cost(Result))
    ;   Result = failed(Status)
    ),
    (   Result = cost(CPU, Stack, Inferences, Outcome)
    ->  MBs is Length / 1048576,
        PerMB is round(Inferences/MBs),
        format("~w~t~34|~D~t~12+~3f~t~10+~1f~t~12+~D~t~14+~w~n",
               [Name, Length, CPU/MBs, Stack/1048576/MBs, PerMB, Outcome])
    ;   format("~w~t~34|~D~t~12+~w~n", [Name, Length, Result])
    ).

%   repeated(+Unit, +Bytes, -Text): about Bytes characters of Unit
%   repeated, or of nested(Open, Close): all the Opens, then all the
%   Closes.

repeated(nested(Open, Close), Bytes, Text) :-
    !,
    Half is Bytes // 2,
    repeated(Open, Half, Opens),
    repeated(Close, Half, Closes),
    string_concat(Opens, Closes, Text).
repeated(Unit, Bytes, Text) :-
    string_length(Unit, UnitLength),
    N is max(1, Bytes // UnitLength),
    length(Units, N),
    maplist(=(Unit), Units),
    atomics_to_string(Units, Text).

%   measure(+Param, -Cost): parse Param as the statements of a
%   request, in this thread; Cost is cost(CPU, StackBytes, Inferences,
%   Outcome).

measure(Param, cost(CPU, Stack, Inferences, Outcome)) :-
    garbage_collect,
    statistics(inferences, I0),
    statistics(cputime, T0),
    catch(( oro_parse_budget(( oro_parse_collection(set, Param, Elements),
                               oro_statements(Elements, _, _)
                             )),
            Outcome = ok
          ),
          error(Formal, _),
          outcome(Formal, Outcome)),
    statistics(cputime, T1),
    statistics(inferences, I1),
    Inferences is I1 - I0,
    statistics(global, Global),
    statistics(local, Local),
    statistics(trail, Trail),
    Stack is Global + Local + Trail,
    CPU is T1 - T0.

outcome(resource_error(Resource), Name) :-
    !,
    functor(Resource, Name, _).
outcome(Formal, Name) :-
    (   compound(Formal)
    ->  arg(1, Formal, First),
        (   compound(First)
        ->  functor(First, Name, _)
        ;   functor(Formal, Name, _)
        )
    ;   Name = Formal
    ).
