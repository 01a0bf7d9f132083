/*  The same server, its client a thread of its process or another process.

        swipl bench/bench_switch.pl [--facts=100000] [--samples=300]
                                    [--rounds=2] [--pin=0]

    A client in another process makes the CPU switch address spaces
    twice a round trip; a client that is a thread of the server's own
    process does not.  On a machine where that switch is dear (a
    nested virtual machine, where a TLB miss is), a request that
    touches much memory, a find, pays more for it than the echo.
    This benchmark tells that cost apart from the server's own work.

    This process starts the oro server (oro_server_start/2, port 0) and
    the echo server of bench_common, and loads bench_full.pl's world of
    `facts` triples with oro_add/2.  Then, `rounds` times, it measures
    over the socket the echo round trip and bench_full's check, lookup
    and find requests (the same texts, `samples` of each), first from a
    thread of this process, then from a child process (this script with
    --client), one after the other.  Printed: the median of the rounds'
    medians for each request and client, and its ratio to the echo
    round trip of the same client.

    --pin=CPU (default 0; --pin=none leaves the processes to the
    scheduler) runs this process and the child on that one CPU, so both
    clients share a core with the server, as in bench_full.pl --pin.
*/

:- module(bench_switch, []).

:- prolog_load_context(directory, Dir),
   asserta(user:file_search_path(oro_bench, Dir)),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(main), [argv_options/3]).
:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(process)).
:- use_module(library(error)).
:- use_module(bench_common).
:- use_module('../server/oro_server').
:- user:load_files(oro_bench(bench_full), [if(not_loaded)]).

:- prolog_load_context(file, File),
   (   current_prolog_flag(associated_file, File)
   ->  initialization(main, main)
   ;   true
   ).

opt_type(facts, facts, nonneg).
opt_type(samples, samples, nonneg).
opt_type(rounds, rounds, nonneg).
opt_type(pin, pin, atom).
opt_type(client, client, boolean).
opt_type(port, port, nonneg).
opt_type(echo_port, echo_port, nonneg).

%   The requests measured: keys of bench_full's op/9 that read the
%   store only, so that every round and client finds the same world.

request(check_asserted).
request(check_property).
request(lookup_name).
request(find_1).
request(find_2).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(facts(Facts), Options, 100000),
    option(samples(Samples), Options, 300),
    must_be(positive_integer, Facts),
    must_be(positive_integer, Samples),
    user:world(Facts, World),
    (   option(client(true), Options)
    ->  option(port(Port), Options),
        option(echo_port(EchoPort), Options),
        client_figures(Port, EchoPort, World, Samples, Figures),
        format("~q.~n", [Figures])
    ;   option(rounds(Rounds), Options, 2),
        must_be(positive_integer, Rounds),
        option(pin(Pin), Options, '0'),
        pin(Pin),
        bench_machine,
        host(World, Rounds, Samples, Pin)
    ).

pin(none) :-
    !.
pin(CPU) :-
    atom_number(CPU, N),
    bench_pin_to_cpu(N).

%   host(+World, +Rounds, +Samples, +Pin): the servers in this process,
%   the world loaded, the rounds measured and the table printed.

host(World, Rounds, Samples, Pin) :-
    get_time(Start),
    nb_setval(bench_start, Start),          % bench_full's progress/2
    oro_server_start([port(0)], Server),
    oro_server_port(Server, Port),
    user:load_world(in_process, World, _),
    bench_echo_start(0, Echo),
    numlist(1, Rounds, Rs),
    maplist(round(Port, Echo.port, World, Samples), Rs, PerRound),
    bench_echo_stop(Echo),
    oro_server_stop(Server),
    format("~n~D triples, ~D samples a request, ~d rounds, CPU ~w~n~n",
           [World.size, Samples, Rounds, Pin]),
    format("| request | client thread | x echo | client process | x echo | \c
            process - thread |~n|---|---|---|---|---|---|~n"),
    forall(( Key = echo ; request(Key) ),
           print_row(Key, PerRound)).

round(Port, EchoPort, World, Samples, R, thread(Thread)-process(Process)) :-
    format(user_error, "round ~d: client thread~n", [R]),
    client_figures(Port, EchoPort, World, Samples, Thread),
    format(user_error, "round ~d: client process~n", [R]),
    client_process(Port, EchoPort, World, Samples, Process).

%   client_process(+Port, +EchoPort, +World, +Samples, -Figures): this
%   script as a client in a child process; it prints its figures as a
%   term.

client_process(Port, EchoPort, World, Samples, Figures) :-
    module_property(bench_switch, file(Self)),
    format(atom(P), '--port=~d', [Port]),
    format(atom(E), '--echo_port=~d', [EchoPort]),
    format(atom(F), '--facts=~d', [World.size]),
    format(atom(S), '--samples=~d', [Samples]),
    process_create(path(swipl), [Self, '--client', P, E, F, S],
                   [stdout(pipe(Out)), process(Pid)]),
    call_cleanup(read_term(Out, Figures, []), close(Out)),
    process_wait(Pid, Status),
    (   Status == exit(0),
        is_list(Figures)
    ->  true
    ;   throw(error(bench_client(Status, Figures), _))
    ).

%   client_figures(+Port, +EchoPort, +World, +Samples, -Figures): the
%   median of each request over the socket, Key-Micros, `echo` first.

client_figures(Port, EchoPort, W, Samples, [echo-Echo|Figures]) :-
    N is Samples + 5,
    Params = params{samples:Samples, budget:15},
    bench_with_connection(
        EchoPort, E,
        user:measure(N, Params, I, bench_call(E, check, [[S]], "true"),
                     asserted_statement(W, I, S), _, EchoStats)),
    Echo = EchoStats.median,
    findall(Key, request(Key), Keys),
    bench_with_connection(Port, C,
                          maplist(request_median(C, W, N, Params), Keys,
                                  Figures)).

request_median(C, W, N, Params, Key, Key-Median) :-
    once(user:op(Key, _, _, C, W, done{}, I, Goal, Prepare)),
    user:measure(N, Params, I, Goal, Prepare, _, Stats),
    Median = Stats.median.

print_row(Key, PerRound) :-
    placement_median(thread, Key, PerRound, T),
    placement_median(process, Key, PerRound, P),
    placement_median(thread, echo, PerRound, TE),
    placement_median(process, echo, PerRound, PE),
    (   Key == echo
    ->  Label = "echo round trip (floor)"
    ;   once(user:op(Key, Label, _, _, _, _, _, _, _))
    ),
    TR is T / TE,
    PR is P / PE,
    D is P - T,
    format("| ~w | ~1f µs | ~1fx | ~1f µs | ~1fx | ~1f µs |~n",
           [Label, T, TR, P, PR, D]).

placement_median(Placement, Key, PerRound, Median) :-
    findall(M, ( member(Round, PerRound),
                 placement_figures(Placement, Round, Figures),
                 memberchk(Key-M, Figures)
               ), Ms),
    msort(Ms, Sorted),
    length(Sorted, L),
    Mid is L // 2,
    nth0(Mid, Sorted, Median).

placement_figures(thread, thread(F)-_, F).
placement_figures(process, _-process(F), F).
