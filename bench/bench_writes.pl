/*  What a request costs the server, every thread of it counted:

        swipl bench/bench_writes.pl [--requests=N] [--pin=CPU]

    The real server (a child process, the bundled ontology) is sent, on
    one connection, N requests (default 10,000) of each kind in turn:
    add one new statement, update a functional property
    (`updI isVisible true|false`, fifty subjects), check a statement.
    For each kind: the median and p99 of the round trip, the CPU time
    the server spent (every thread, from /proc/PID/task/*/stat) per
    request, and the part of it SWI-Prolog's `gc` thread took (clause
    and atom garbage collection, which writes that retract clauses
    cause: see oro_store, "Writes leave no clause behind").  The kinds
    run twice, as the cost of the collectors grows with the store.
    --pin=CPU runs this process and the server on that one CPU
    (bench_common:bench_pin_to_cpu/1).  Linux only (/proc).
*/

:- initialization(main, main).

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(main), [argv_options/3]).
:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(readutil)).
:- use_module(library(filesex)).
:- use_module(library(process)).
:- use_module(library(error)).
:- use_module(library(aggregate)).
:- use_module(bench_common).

opt_type(requests, requests, nonneg).
opt_type(pin, pin, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(requests(N), Options, 10000),
    must_be(positive_integer, N),
    bench_pin_option(Options),
    bench_machine,
    format("~n| round | request | median | p99 | server CPU a request \c
            | of which the gc thread |~n|---|---|---|---|---|---|~n"),
    flush_output,
    bench_with_server([], Port, Pid,
                      bench_with_connection(Port, Conn,
                                            forall(( between(1, 2, Round),
                                                     member(Kind, [add, update, check])
                                                   ),
                                                   row(Conn, Pid, N, Round, Kind)))).

%   row(+Conn, +Pid, +N, +Round, +Kind): N requests of Kind, one row.

row(Conn, Pid, N, Round, Kind) :-
    server_cpu(Pid, Total0, Gc0),
    findall(T, ( between(1, N, I),
                 request(Kind, Round, I, Method, Params),
                 bench_time(bench_call(Conn, Method, Params), T)
               ), Times),
    server_cpu(Pid, Total, Gc),
    bench_summary(Times, Median, P99),
    PerRequest is (Total - Total0) / N,
    GcPerRequest is (Gc - Gc0) / N,
    format("| ~d | ~w | ~1f us | ~1f us | ~1f us | ~1f us |~n",
           [Round, Kind, Median, P99, PerRequest, GcPerRequest]).

request(add, Round, I, add, [[S]]) :-
    F is I mod 50,
    format(string(S), "w~d_~d isOn furniture~d", [Round, I, F]).
request(update, _, I, update, [[S]]) :-
    K is I mod 50,
    (   (I // 50) mod 2 =:= 0
    ->  V = true
    ;   V = false
    ),
    format(string(S), "upd~d isVisible ~w", [K, V]).
request(check, _, _, check, [["w1_1 isOn furniture1"]]).

%   server_cpu(+Pid, -Micros, -GcMicros): the CPU time (user and system)
%   of every thread of process Pid so far, and of its thread named gc.

server_cpu(Pid, Micros, GcMicros) :-
    format(atom(Dir), '/proc/~w/task', [Pid]),
    directory_files(Dir, Entries),
    exclude([E]>>sub_atom(E, 0, _, _, '.'), Entries, Tasks),
    foldl(task_cpu(Dir), Tasks, 0-0, Ticks-GcTicks),
    clock_ticks(Hz),
    Micros is Ticks * 1.0e6 / Hz,
    GcMicros is GcTicks * 1.0e6 / Hz.

task_cpu(Dir, Task, Ticks0-Gc0, Ticks-Gc) :-
    format(atom(Stat), '~w/~w/stat', [Dir, Task]),
    catch(read_file_to_string(Stat, Text, []), _, fail),
    stat_fields(Text, Name, Fields),
    !,
    nth1(12, Fields, U),                % utime, stime: fields 14 and 15
    nth1(13, Fields, S),
    number_string(UN, U),
    number_string(SN, S),
    Ticks is Ticks0 + UN + SN,
    (   Name == "gc"
    ->  Gc is Gc0 + UN + SN
    ;   Gc = Gc0
    ).
task_cpu(_, _, Acc, Acc).                   % the thread ended meanwhile

%   stat_fields(+Text, -Name, -Fields): the thread name of a stat line
%   (between the first `(` and the last `)`) and the fields after it,
%   from the third (state) on.

stat_fields(Text, Name, Fields) :-
    sub_string(Text, Open, 1, _, "("),
    !,
    aggregate_all(max(C), sub_string(Text, C, 1, _, ")"), Close),
    NameStart is Open + 1,
    NameLength is Close - NameStart,
    sub_string(Text, NameStart, NameLength, _, Name),
    AfterName is Close + 2,
    sub_string(Text, AfterName, _, 0, Rest),
    split_string(Rest, " ", " \n", Fields).

clock_ticks(Hz) :-
    setup_call_cleanup(
        process_create(path(getconf), ['CLK_TCK'],
                       [stdout(pipe(Out)), process(Proc)]),
        read_line_to_string(Out, Line),
        ( close(Out), process_wait(Proc, _) )),
    number_string(Hz, Line).
