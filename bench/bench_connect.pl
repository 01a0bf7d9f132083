/*  Connecting: a client that connects, asks one thing and leaves.

        swipl bench/bench_connect.pl [--samples=N] [--pin=CPU]

    Some clients open a connection for each request (a shell script
    around telnet or netcat, a ROS node that connects per service
    call).  This times N (default 1,000) rounds of: connect, one
    `check` of one statement, read the reply, close.  Against the real
    server (a child process, common-sense ontology) and, as the floor,
    against the echo server of bench_common, which makes a thread for
    each connection.  Then, for scale, the same `check` on one
    connection kept open.  --pin=CPU runs every process on that one CPU
    (see bench_full.pl).
*/

:- use_module(library(main), [argv_options/3]).
:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(samples, samples, nonneg).
opt_type(pin, pin, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(samples(N), Options, 1000),
    bench_pin_option(Options),
    bench_machine,
    format("~n| server | connect, check, close: median | p99 | check on an open \c
            connection: median | p99 |~n|---|---|---|---|---|~n"),
    bench_echo_start(0, Echo),
    call_cleanup(row(Echo.port, "echo (floor)", N), bench_echo_stop(Echo)),
    bench_with_server([], Port, _, row(Port, "oro", N)).

%   row(+Port, +Server, +N): N checks each on a new connection, then N
%   on one connection.

row(Port, Server, N) :-
    check(Port),                            % the server is ready
    bench_measure(N, _, check(Port), true, Each),
    bench_with_connection(Port, Conn,
                          bench_measure(N, _, check_on(Conn), true, Kept)),
    bench_summary(Each, EachMedian, EachP99),
    bench_summary(Kept, KeptMedian, KeptP99),
    maplist(bench_micros, [EachMedian, EachP99, KeptMedian, KeptP99], Texts),
    format("| ~s | ~w | ~w | ~w | ~w |~n", [Server|Texts]),
    flush_output.

check(Port) :-
    bench_with_connection(Port, Conn, check_on(Conn)).

check_on(Conn) :-
    bench_call(Conn, check, [["myself rdf:type Robot"]]).
