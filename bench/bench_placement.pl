/*  One batch at a time, and where the client and the server run.

        swipl bench/bench_placement.pl [--facts=100000] [--rounds=3]
                                       [--samples=200]

    A client that sends its adds of 100 statements one at a time waits
    for each reply before it sends the next: the client and the server
    take turns, and each turn wakes the other.  This benchmark measures
    how much that costs with each placement of the two processes:

      - free: as the scheduler places them;
      - apart: the server on CPU 0, the client (this process) on CPU 1;
      - together: both on CPU 0.

    With each placement: a fresh server (server/oro_server.pl) and an
    echo server with oro's framing and none of its work (bench_full.pl
    --echo) are started on the server's CPUs;
    then, from the client's CPUs, `samples` round trips of one add of
    100 statements to the echo server (its median), and the load of the
    world of bench_world/2 (`facts` triples) into the server in adds of
    100, one at a time, the requests' texts made beforehand (wall-clock
    time of the whole load).

    Each round runs every placement once, one after the other, so that
    a slow spell of the machine falls on all of them; printed are the
    medians over the rounds.  On a machine with one CPU, `apart` is
    left out.  A table on stdout.
*/

:- prolog_load_context(directory, Dir),
   asserta(user:file_search_path(oro_bench, Dir)).

:- use_module(library(main), [argv_options/3]).
:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(error)).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(facts, facts, nonneg).
opt_type(rounds, rounds, nonneg).
opt_type(samples, samples, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(facts(Facts), Options, 100000),
    option(rounds(Rounds), Options, 3),
    option(samples(Samples), Options, 200),
    must_be(positive_integer, Facts),
    must_be(positive_integer, Rounds),
    must_be(positive_integer, Samples),
    bench_machine,
    bench_cpus(All),
    placements(All, Placements),
    bench_world(Facts, World),
    bench_batches(World, 100, Batches0),
    maplist(bench_quoted, Batches0, Batches),
    length(Batches, NBatches),
    format("~nWorld: ~D statements, ~D adds of 100, one at a time; \c
            ~d rounds.~n~n", [Facts, NBatches, Rounds]),
    numlist(1, Rounds, Rs),
    maplist(round(All, Placements, Samples, Batches), Rs, PerRound),
    report(Placements, Facts, PerRound).

%   placements(+AllCPUs, -Placements): place(Name, ServerCPUs,
%   ClientCPUs) for each placement this machine can have.

placements(All, Placements) :-
    current_prolog_flag(cpu_count, N),
    findall(place(Name, Server, Client),
            ( placement(Name, Server0, Client0, Min),
              N >= Min,
              cpus(Server0, All, Server),
              cpus(Client0, All, Client)
            ),
            Placements).

placement(free,     all, all, 1).
placement(apart,    0,   1,   2).
placement(together, 0,   0,   1).

cpus(all, All, All) :- !.
cpus(CPU, _, CPU).

%   round(+AllCPUs, +Placements, +Samples, +Batches, +Round, -Figures):
%   Figures is a list Name-figures{echo:Micros, per_s:Rate}, one for
%   each placement.

round(All, Placements, Samples, Batches, Round, Figures) :-
    format(user_error, "round ~d~n", [Round]),
    maplist(placement_figures(All, Samples, Batches), Placements, Figures).

placement_figures(All, Samples, Batches,
                  place(Name, ServerCPUs, ClientCPUs),
                  Name-figures{echo:RoundTrip, per_s:Rate}) :-
    format(user_error, "  ~w: server on ~w, client on ~w~n",
           [Name, ServerCPUs, ClientCPUs]),
    absolute_file_name(oro_bench('bench_full.pl'), Echo,
                       [access(read)]),
    setup_call_cleanup(
        bench_set_cpus(ServerCPUs),             % the children's CPUs
        bench_with_script(
            Echo, ['--echo'], EchoPort, _,
            bench_with_server(
                [], Port, _,
                ( bench_set_cpus(ClientCPUs),
                  echo_round_trip(EchoPort, Samples, Batches, RoundTrip),
                  load(Port, Batches, Rate)
                ))),
        bench_set_cpus(All)).

%   echo_round_trip(+Port, +Samples, +Batches, -Median): the median
%   round trip of Samples adds of 100 (the first batches' texts) to the
%   echo server on Port, in microseconds.

echo_round_trip(Port, Samples, Batches, Median) :-
    bench_with_connection(
        Port, Conn,
        bench_measure(Samples, I, bench_call(Conn, add, [B]),
                      sample_batch(Batches, I, B), Times)),
    bench_summary(Times, Median, _).

sample_batch(Batches, I, Batch) :-
    length(Batches, N),
    J is I mod N,
    nth0(J, Batches, Batch).

%   load(+Port, +Batches, -Rate): statements a second of adding Batches
%   to the server on Port, one request at a time.

load(Port, Batches, Rate) :-
    bench_with_connection(
        Port, Conn,
        bench_time(forall(member(B, Batches), bench_call(Conn, add, [B])),
                   Micros)),
    length(Batches, N),
    Rate is N * 100 / (Micros / 1.0e6).

report(Placements, Facts, PerRound) :-
    format("| placement | server on | client on | echo, add of 100 | \c
            load of ~D, one add at a time | a batch |~n\c
            |---|---|---|---|---|---|~n", [Facts]),
    forall(member(place(Name, Server, Client), Placements),
           report_row(Name, Server, Client, PerRound)).

report_row(Name, Server, Client, PerRound) :-
    findall(Echo0-Rate0,
            ( member(Figures, PerRound),
              memberchk(Name-figures{echo:Echo0, per_s:Rate0}, Figures)
            ), Pairs),
    pairs_keys_values(Pairs, Echoes, Rates),
    bench_summary(Echoes, Echo, _),
    bench_summary(Rates, Rate, _),
    min_list(Rates, Min),
    max_list(Rates, Max),
    Batch is 100 / Rate * 1.0e6,
    bench_micros(Echo, EchoText),
    bench_micros(Batch, BatchText),
    format("| ~w | ~w | ~w | ~w | ~D stmt/s (~D-~D) | ~w |~n",
           [Name, Server, Client, EchoText, round(Rate), round(Min),
            round(Max), BatchText]).
