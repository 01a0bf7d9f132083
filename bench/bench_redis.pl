/*  Several robots through Redis: replication lag, catch-up, add cost.

        swipl bench/bench_redis.pl [--seconds=S] [--missed=N]

    Starts its own redis-server (loopback, a free port, a temporary
    directory, no persistence) and three oro servers (child processes):
    robot_a publishes its model, robot_b and robot_c follow it.

      - lag: a writer sends robot_a adds at a steady pace for S seconds
        (default 3), at 1,000 and 10,000 changes (statements) a second
        (1,000 adds a second of 1 and of 10 statements); one add in 50
        carries a marker statement, and a second thread polls
        `findForAgent robot_a` on robot_b until the marker is there:
        the lag is the time from robot_a's `ok` to the first answer
        that shows it (polling round trip included);
      - catch-up: robot_c (with --db) is killed with kill -9, robot_a
        gets N more statements (default 100,000, in adds of 10), robot_c
        is started again: the time from its start to the moment it
        shows the last statement, and the rate (statements/s);
      - add cost: in this process, oro_add/2 of one statement, without
        and with publishing to Redis (median and p99 of the wall-clock
        time, and the CPU time of the writing thread: the publisher
        thread and Redis run on the same two cores).
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
:- use_module(library(socket)).
:- use_module(library(error)).
:- use_module(library(redis)).
:- use_module(library(oro)).
:- use_module(library(oro/replication/oro_redis)).
:- use_module(bench_common).

opt_type(seconds, seconds, number).
opt_type(missed, missed, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(seconds(Seconds), Options, 3),
    option(missed(Missed), Options, 100000),
    bench_machine,
    with_redis(Port, run(Port, Seconds, Missed)).

run(Port, Seconds, Missed) :-
    format(atom(URL), '--redis=redis://127.0.0.1:~w', [Port]),
    tmp_file(oro_db, Db),
    format(atom(DbArg), '--db=~w', [Db]),
    CArgs = ['--no-kb', URL, '--node=robot_c', '--follow=robot_a', DbArg],
    bench_with_server(['--no-kb', URL, '--node=robot_a'], PA, _,
      bench_with_server(['--no-kb', URL, '--node=robot_b', '--follow=robot_a'],
                        PB, _,
        ( format("~n| changes/s | statements an add | adds | lag median \c
                  | lag p99 | samples |~n|---|---|---|---|---|---|~n"),
          lag_row(PA, PB, 1000, 1, Seconds),
          lag_row(PA, PB, 1000, 10, Seconds),
          catch_up(PA, CArgs, Missed)
        ))),
    delete_directory_and_contents(Db),
    add_cost(Port).

		 /*******************************
		 *             LAG              *
		 *******************************/

lag_row(PA, PB, AddsPerSecond, PerAdd, Seconds) :-
    N is round(AddsPerSecond * Seconds),
    message_queue_create(Samples),
    thread_create(sampler(PB, Samples), Sampler, []),
    bench_with_connection(PA, A,
                          write_paced(A, N, AddsPerSecond, PerAdd, Samples)),
    thread_send_message(Samples, done),
    thread_join(Sampler, exited(Lags)),
    message_queue_destroy(Samples),
    bench_stats(Lags, Stats),
    Rate is AddsPerSecond * PerAdd,
    length(Lags, K),
    format("| ~D | ~w | ~D | ~1f ms | ~1f ms | ~w |~n",
           [Rate, PerAdd, N, Stats.median/1000, Stats.p99/1000, K]),
    flush_output.

write_paced(A, N, AddsPerSecond, PerAdd, Samples) :-
    get_time(T0),
    flag(bench_redis_run, Run, Run+1),
    forall(between(1, N, I),
           ( Due is T0 + I / AddsPerSecond,
             get_time(Now),
             Wait is Due - Now,
             (   Wait > 0
             ->  sleep(Wait)
             ;   true
             ),
             statements(Run, I, PerAdd, Statements, Marker),
             atomic_list_concat(Statements, ', ', Body),
             format(atom(Param), '[~w]', [Body]),
             bench_call(A, add, [Param]),
             (   Marker == none
             ->  true
             ;   get_time(Committed),
                 thread_send_message(Samples, sample(Marker, Committed))
             )
           )).

statements(Run, I, PerAdd, Statements, Marker) :-
    findall(S, ( between(1, PerAdd, J),
                 format(atom(S), 'r~w_~w_~w isIn box~w', [Run, I, J, Run])
               ), Statements0),
    (   I mod 50 =:= 0
    ->  format(atom(Marker), 'mark~w_~w', [Run, I]),
        format(atom(M), 'm~w_~w isIn ~w', [Run, I, Marker]),
        Statements = [M|Statements0]
    ;   Marker = none,
        Statements = Statements0
    ).

%   sampler(+PB, +Queue): for each sample(Marker, Committed), poll
%   robot_b until it shows the marker; exit with the lags (us).

sampler(PB, Queue) :-
    bench_with_connection(PB, B, sample_loop(B, Queue, [], Lags)),
    thread_exit(Lags).

sample_loop(B, Queue, Lags0, Lags) :-
    thread_get_message(Queue, Message),
    (   Message = sample(Marker, Committed)
    ->  format(atom(Pattern), '[?x isIn ~w]', [Marker]),
        get_time(Deadline0),
        Deadline is Deadline0 + 30,
        (   poll(B, Pattern, Deadline)
        ->  get_time(Seen),
            Lag is (Seen - Committed) * 1.0e6,
            sample_loop(B, Queue, [Lag|Lags0], Lags)
        ;   sample_loop(B, Queue, Lags0, Lags)
        )
    ;   Lags = Lags0
    ).

poll(B, Pattern, Deadline) :-
    catch(bench_call(B, findForAgent, [robot_a, '?x', Pattern], Value),
          bench_failed(_, _, _), Value = "[]"),
    (   sub_atom(Value, _, _, _, '"')          % a name: not []
    ->  true
    ;   get_time(Now),
        Now < Deadline
    ->  poll(B, Pattern, Deadline)
    ).

		 /*******************************
		 *           CATCH-UP           *
		 *******************************/

catch_up(PA, CArgs, Missed) :-
    node_spawn(CArgs, Pid1, PC1),
    bench_with_connection(PA, A0, bench_call(A0, add, ['[c0 isIn cbox]'])),
    bench_with_connection(PC1, C1,
                          poll_for(C1, '[?x isIn cbox]', 60)),
    process_kill(Pid1, kill),
    process_wait(Pid1, _),
    Adds is Missed // 10,
    get_time(W0),
    bench_with_connection(PA, A,
                          forall(between(1, Adds, I),
                                 ( findall(S, ( between(1, 10, J),
                                                format(atom(S), 'c~w_~w isIn cbox', [I, J])
                                              ), Ss),
                                   atomic_list_concat(Ss, ', ', Body),
                                   format(atom(P), '[~w]', [Body]),
                                   bench_call(A, add, [P])
                                 ))),
    get_time(W1),
    format(atom(Last), '[c~w_10 isIn ?x]', [Adds]),
    get_time(T0),
    node_spawn(CArgs, Pid2, PC2),
    get_time(T1),
    bench_with_connection(PC2, C2,
                          ( poll_for(C2, Last, 300),
                            get_time(T2),
                            bench_call(C2, findForAgent,
                                       [robot_a, '?x', '[?x isIn cbox]'], V)
                          )),
    split_string(V, ",", "", Parts),
    length(Parts, Seen),
    bench_stop_process(Pid2),
    Total is T2 - T0,
    Rate is Missed / Total,
    WriteRate is Missed / (W1 - W0),
    format("~n| missed statements (adds) | written at | start to listening \c
            | start to caught up | catch-up rate | statements seen |~n\c
            |---|---|---|---|---|---|~n"),
    format("| ~D (~D) | ~D/s | ~2f s | ~2f s | ~D/s | ~D |~n",
           [Missed, Adds, round(WriteRate), T1 - T0, Total, round(Rate),
            Seen]).

poll_for(C, Pattern, Seconds) :-
    get_time(Now),
    Deadline is Now + Seconds,
    poll(C, Pattern, Deadline).

node_spawn(Args, Pid, Port) :-
    bench_server_script(Server),
    process_create(path(swipl), [Server, '--port=0'|Args],
                   [stdout(pipe(Out)), process(Pid)]),
    read_line_to_string(Out, Line),
    close(Out),
    split_string(Line, ":", " ", Parts),
    last(Parts, PortText),
    number_string(Port, PortText).

		 /*******************************
		 *           ADD COST           *
		 *******************************/

add_cost(Port) :-
    oro_init([]),
    N = 20000,
    add_times(N, plain, Plain, Cpu1),
    format(atom(URL), 'redis://127.0.0.1:~w', [Port]),
    oro_redis_start([redis(URL), node(bench_local)]),
    add_times(N, published, Published, Cpu2),
    oro_redis_sync(60),
    oro_redis_stop,
    bench_stats(Plain, S1),
    bench_stats(Published, S2),
    format("~n| oro_add/2 of one statement | median | p99 \c
            | CPU of the writing thread |~n|---|---|---|---|~n"),
    format("| alone | ~1f us | ~1f us | ~1f us |~n",
           [S1.median, S1.p99, Cpu1]),
    format("| publishing to Redis | ~1f us | ~1f us | ~1f us |~n",
           [S2.median, S2.p99, Cpu2]).

%   add_times(+N, +Tag, -Times, -Cpu): N adds of one statement, their
%   wall-clock times and the mean CPU time of this thread an add (us).

add_times(N, Tag, Times, Cpu) :-
    thread_self(Me),
    thread_statistics(Me, cputime, C0),
    bench_measure(N, I, oro_add(myself, [S]),
                  format(string(S), "~w~w isIn box", [Tag, I]), Times),
    thread_statistics(Me, cputime, C1),
    Cpu is (C1 - C0) / N * 1.0e6.

		 /*******************************
		 *            REDIS             *
		 *******************************/

with_redis(Port, Goal) :-
    tcp_socket(S),
    tcp_bind(S, '127.0.0.1':Port),
    tcp_close_socket(S),
    tmp_file(redis, Dir),
    make_directory(Dir),
    setup_call_cleanup(
        process_create(path('redis-server'),
                       [ '--port', Port, '--bind', '127.0.0.1',
                         '--dir', Dir, '--save', '', '--appendonly', no
                       ],
                       [stdout(null), process(Pid)]),
        ( wait_redis(Port, 100),
          once(Goal)
        ),
        ( process_kill(Pid),
          process_wait(Pid, _),
          delete_directory_and_contents(Dir)
        )).

wait_redis(Port, Tries) :-
    (   catch(setup_call_cleanup(
                  redis_connect('127.0.0.1':Port, C, [reconnect(false)]),
                  redis(C, ping, _),
                  redis_disconnect(C)),
              _, fail)
    ->  true
    ;   Tries > 0
    ->  sleep(0.05),
        T is Tries - 1,
        wait_redis(Port, T)
    ).
