/*  oro benchmark: latency of add, check and find, in-process and over
    the socket, at about 10k and 100k asserted triples, and bulk-add
    throughput.

        swipl bench/bench.pl [--sizes=10000,100000] [--samples=300]

    It starts the real server (server/oro_server.pl --port=0) as a
    child process for the socket figures, and prints one table.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)),
   asserta(user:file_search_path(oro_bench, Dir)).

:- use_module(library(oro)).
:- use_module(library(process)).
:- use_module(library(socket)).
:- use_module(library(readutil)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(main), [argv_options/3]).

:- initialization(main, main).

opt_type(sizes, sizes, term).
opt_type(samples, samples, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option_sizes(Options, Sizes),
    (   memberchk(samples(Samples), Options)
    ->  true
    ;   Samples = 300
    ),
    machine,
    format("~n~w~t~34|~w~t~12+~w~t~12+~w~t~12+~w~n",
           [operation, triples, median, p99, 'per second']),
    forall(member(Size, Sizes),
           ( bench_in_process(Size, Samples),
             bench_socket(Size, Samples)
           )).

option_sizes(Options, Sizes) :-
    (   memberchk(sizes(Term), Options)
    ->  (   integer(Term)
        ->  Sizes = [Term]
        ;   Term = (A,B)
        ->  comma_list((A,B), Sizes)
        ;   Sizes = Term
        )
    ;   Sizes = [10000, 100000]
    ).

machine :-
    current_prolog_flag(version, V),
    catch(( read_file_to_string('/proc/cpuinfo', CPU, []),
            sub_string(CPU, B, _, _, "model name"),
            sub_string(CPU, B, 80, _, L0),
            split_string(L0, "\n", "", [Line|_])
          ), _, Line = "unknown cpu"),
    format("SWI-Prolog ~w; ~w~n", [V, Line]).

		 /*******************************
		 *          THE WORLD           *
		 *******************************/

%   A synthetic robot world: objects typed under common-sense classes,
%   placed on furniture, coloured and visible: 4 triples an object.

world_statements(Triples, Statements) :-
    Objects is Triples // 4,
    findall(S, ( between(1, Objects, I), object_statement(I, S) ), Statements).

object_statement(I, S) :-
    class(I, Class),
    F is I mod 50,
    color(I, Color),
    V is I mod 2,
    (   S = format("obj~d rdf:type ~w", [I, Class])
    ;   S = format("obj~d isOn furniture~d", [I, F])
    ;   S = format("obj~d hasColor ~w", [I, Color])
    ;   V =:= 0
    ->  S = format("obj~d isVisible true", [I])
    ;   S = format("obj~d isVisible false", [I])
    ).

class(I, C) :-
    nth0(N, ['Cup', 'Book', 'Box', 'Toy', 'Plate', 'VideoTape', 'Bottle'], C),
    N =:= I mod 7,
    !.

color(I, C) :-
    nth0(N, [red, green, blue, yellow, black, white], C),
    N =:= I mod 6,
    !.

statement_text(format(F, A), Text) :-
    format(string(Text), F, A).

batches(List, N, [Batch|Batches]) :-
    length(Batch, N),
    append(Batch, Rest, List),
    !,
    batches(Rest, N, Batches).
batches([], _, []) :- !.
batches(List, _, [List]).

		 /*******************************
		 *          IN PROCESS          *
		 *******************************/

bench_in_process(Size, Samples) :-
    oro_init([]),
    world_statements(Size, World),
    maplist(statement_text, World, Texts),
    batches(Texts, 100, Batches),
    length(Texts, NStmts),
    get_time(T0),
    forall(member(B, Batches), oro_add(myself, B)),
    get_time(T1),
    Rate is NStmts / max(0.000001, T1-T0),
    row('in-process bulk add (batches of 100)', Size, -, -, Rate),
    Objects is Size // 4,
    measure(Samples, I, oro_add(myself, [Stmt]),
            format(string(Stmt), "extra~d isOn furniture1", [I]), Add),
    report('in-process add 1', Size, Add),
    measure(Samples, I, oro_check(myself, [Stmt]),
            ( J is 1 + I mod Objects, F is J mod 50,
              format(string(Stmt), "obj~d isOn furniture~d", [J, F]) ), Check),
    report('in-process check (asserted)', Size, Check),
    measure(Samples, I, oro_check(myself, [Stmt]),
            ( J is 1 + I mod Objects,
              format(string(Stmt), "obj~d rdf:type Artifact", [J]) ), CheckInf),
    report('in-process check (inferred type)', Size, CheckInf),
    measure(Samples, I, oro_find(myself, o, [P], _),
            ( F is I mod 50,
              format(string(P), "?o isAt furniture~d", [F]) ), Find1),
    report('in-process find (1 pattern)', Size, Find1),
    measure(Samples, I, oro_find(myself, o, [P1, P2], _),
            ( F is I mod 50,
              format(string(P1), "?o isAt furniture~d", [F]),
              P2 = "?o rdf:type Tableware" ), Find2),
    report('in-process find (2 patterns)', Size, Find2).

		 /*******************************
		 *          OVER SOCKET         *
		 *******************************/

bench_socket(Size, Samples) :-
    absolute_file_name(oro_bench('../server/oro_server.pl'), Server,
                       [access(read)]),
    setup_call_cleanup(
        process_create(path(swipl), [Server, '--port=0'],
                       [stdout(pipe(Out)), process(Pid)]),
        ( read_line_to_string(Out, Line),
          split_string(Line, ":", " ", Parts),
          last(Parts, PortText),
          number_string(Port, PortText),
          bench_client(Port, Size, Samples)
        ),
        ( process_kill(Pid),
          process_wait(Pid, _),
          close(Out)
        )).

bench_client(Port, Size, Samples) :-
    setup_call_cleanup(
        ( tcp_connect('127.0.0.1':Port, Pair, []),
          stream_pair(Pair, In, Out),
          set_stream(In, encoding(utf8)),
          set_stream(Out, encoding(utf8))
        ),
        socket_figures(In-Out, Size, Samples),
        close(Pair)).

socket_figures(C, Size, Samples) :-
    world_statements(Size, World),
    maplist(statement_text, World, Texts),
    batches(Texts, 100, Batches),
    length(Texts, NStmts),
    get_time(T0),
    forall(member(B, Batches), call_ok(C, add, [B])),
    get_time(T1),
    Rate is NStmts / max(0.000001, T1-T0),
    row('socket bulk add (batches of 100)', Size, -, -, Rate),
    Objects is Size // 4,
    measure(Samples, I, call_ok(C, add, [[S]]),
            format(string(S), "extra~d isOn furniture1", [I]), Add),
    report('socket add 1', Size, Add),
    measure(Samples, I, call_ok(C, check, [[S]]),
            ( J is 1 + I mod Objects, F is J mod 50,
              format(string(S), "obj~d isOn furniture~d", [J, F]) ), Check),
    report('socket check (asserted)', Size, Check),
    measure(Samples, I, call_ok(C, check, [[S]]),
            ( J is 1 + I mod Objects,
              format(string(S), "obj~d rdf:type Artifact", [J]) ), CheckInf),
    report('socket check (inferred type)', Size, CheckInf),
    measure(Samples, I, call_ok(C, find, ["o", [P]]),
            ( F is I mod 50,
              format(string(P), "?o isAt furniture~d", [F]) ), Find1),
    report('socket find (1 pattern)', Size, Find1),
    measure(Samples, I, call_ok(C, find, ["o", [P1, P2]]),
            ( F is I mod 50,
              format(string(P1), "?o isAt furniture~d", [F]),
              P2 = "?o rdf:type Tableware" ), Find2),
    report('socket find (2 patterns)', Size, Find2).

call_ok(In-Out, Method, Params) :-
    format(Out, "~w~n", [Method]),
    forall(member(P, Params), write_param(Out, P)),
    format(Out, "#end#~n", []),
    flush_output(Out),
    read_line_to_string(In, Status),
    read_line_to_string(In, _Value),
    read_line_to_string(In, End),
    (   Status == "ok", End == "#end#"
    ->  true
    ;   throw(bench_failed(Method, Status))
    ).

write_param(Out, List) :-
    is_list(List),
    !,
    atomic_list_concat(List, ', ', Text),
    format(Out, "[~w]~n", [Text]).
write_param(Out, Text) :-
    format(Out, "~w~n", [Text]).

		 /*******************************
		 *          MEASURING           *
		 *******************************/

%   measure(+N, ?I, :Goal, :Prepare, -Times): run Prepare then Goal for
%   I in 1..N; Times are the Goal's wall times in µs.

:- meta_predicate measure(+, ?, 0, 0, -).

measure(N, I, Goal, Prepare, Times) :-
    findall(T, ( between(1, N, I),
                 once(Prepare),
                 get_time(T0),
                 once(Goal),
                 get_time(T1),
                 T is (T1-T0)*1.0e6
               ), Times).

report(Name, Size, Times) :-
    msort(Times, Sorted),
    length(Sorted, N),
    M is N // 2,
    nth0(M, Sorted, Median),
    P is min(N-1, (N*99) // 100),
    nth0(P, Sorted, P99),
    PerSecond is 1.0e6 / Median,
    row(Name, Size, Median, P99, PerSecond).

row(Name, Size, Median, P99, PerSecond) :-
    micros(Median, MText),
    micros(P99, PText),
    format("~w~t~34|~d~t~12+~w~t~12+~w~t~12+~0f~n",
           [Name, Size, MText, PText, PerSecond]),
    flush_output.

micros(X, Text) :-
    (   number(X)
    ->  format(string(Text), "~1f us", [X])
    ;   Text = "-"
    ).
