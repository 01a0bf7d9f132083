/*  oro benchmark: agent models and memory profiles.

        swipl bench/bench_agents.pl [--samples=300] [--facts=100000]
                                    [--time-base=500] [--checkers=4]
                                    [--spread-facts=60000]
                                    [--spread-seconds=3]
                                    [--spread-batch=20]
                                    [--case=all]

    - addForAgent over the socket with 1, 10 and 100 agent models
      (median and p99 of single-statement adds spread over the agents;
      add on the robot's model for comparison), and the time to create
      the agent models;
    - memory per agent model: process RSS and rdf_db triples before and
      after creating 100 agents, in process and in the server process;
    - forgetting: `facts` SHORTTERM facts added in one request, so that
      they share one deadline (10 time units later); the time from that
      deadline until they are all gone, and the latency of `check`
      requests sent meanwhile by concurrent clients (before the
      deadline, and from the deadline until the facts are gone).  The
      time base must leave time to add the facts before they expire;
    - forgetting spread-out deadlines: `spread-facts` SHORTTERM facts
      added in batches of `spread-batch` at a steady pace over
      `spread-seconds`, so that they have as many deadlines as batches
      (in process); the CPU time of the memory scheduler thread while
      they expire (from the first deadline until the last fact is
      gone), and the lateness of each fact (from its deadline until a
      watcher saw it gone: median, p99, max, and that of the last fact).
      The CPU time of the scheduler is also given for the facts added at
      once.  The lifetime (10 time units) must be longer than
      `spread-seconds`.

    - the first query after a schema change (in process, `facts`
      triples of bench_world/2 and 10 agents): after each of
      `samples`/10 schema changes (a new sub-class of Artifact), one
      find on each model; with the setting oro_events:warm_schemas
      off, that query compiles the model's schema tables; on, the
      watcher thread has compiled them ahead (the rows wait until it
      has, then time the query).

    --case=all (default), agents (addForAgent and memory per agent),
    forget (facts added at once), spread (spread-out deadlines) or
    schema (the first query after a schema change) runs only those
    figures.

    The agent figures over the socket come from the real server
    (server/oro_server.pl --port=0) started as a child process; the
    forgetting figures over the socket from a server started in this
    process (to read the exact deadline), its clients being threads.
    Prints tables.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)),
   asserta(user:file_search_path(oro_bench, Dir)).

:- use_module(library(oro)).
:- use_module(library(oro/oro_memory), [oro_memory_sync/0]).
:- use_module(library(oro/reason/oro_reason), [oro_compiled_schema/2]).
:- use_module(library(oro/oro_store), [oro_model/1]).
:- use_module(library(settings)).
:- use_module(library(yall)).
:- use_module(oro_bench('../server/oro_server')).
:- use_module(library(readutil)).
:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(aggregate)).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(http/json)).
:- use_module(library(main), [argv_options/3]).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(samples, samples, nonneg).
opt_type(facts, facts, nonneg).
opt_type(time_base, time_base, nonneg).
opt_type(checkers, checkers, nonneg).
opt_type(spread_facts, spread_facts, nonneg).
opt_type(spread_seconds, spread_seconds, number).
opt_type(spread_batch, spread_batch, nonneg).
opt_type(case, case, oneof([all, agents, forget, spread, schema])).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(samples(Samples), Options, 300),
    option(facts(Facts), Options, 100000),
    option(time_base(TimeBase), Options, 500),
    option(checkers(Checkers), Options, 4),
    option(spread_facts(SpreadFacts), Options, 60000),
    option(spread_seconds(SpreadSeconds), Options, 3),
    option(spread_batch(SpreadBatch), Options, 20),
    option(case(Case), Options, all),
    bench_machine,
    (   case(Case, agents)
    ->  bench_add_for_agent(Samples),
        bench_memory_per_agent(100)
    ;   true
    ),
    (   case(Case, forget)
    ->  bench_forgetting(Facts, TimeBase, Checkers)
    ;   true
    ),
    (   case(Case, spread)
    ->  bench_forgetting_spread(SpreadFacts, SpreadSeconds, SpreadBatch,
                                TimeBase)
    ;   true
    ),
    (   case(Case, schema)
    ->  bench_first_query(Facts, Samples)
    ;   true
    ),
    oro_events_sync,
    oro_memory_sync.

case(all, _) :- !.
case(Case, Case).

		 /*******************************
		 *        SERVER PROCESS        *
		 *******************************/

%   with_server(+Args, -Conn, -Pid, :Goal): run Goal with a connection
%   to a server child process started with Args.

:- meta_predicate with_server(+, -, -, 0).

with_server(Args, Conn, Pid, Goal) :-
    bench_with_server(Args, Port, Pid,
                      bench_with_connection(Port, Conn, Goal)).

%   rss_kb(+Pid, -KB): resident set size of a process.

rss_kb(Pid, KB) :-
    format(atom(File), '/proc/~w/status', [Pid]),
    read_file_to_string(File, Status, []),
    sub_string(Status, B, _, _, "VmRSS:"),
    sub_string(Status, B, 40, _, Line0),
    split_string(Line0, "\n", "", [Line|_]),
    split_string(Line, " \t", " \t", Parts),
    exclude(==(""), Parts, ["VmRSS:", Text|_]),
    number_string(KB, Text).

self_pid(Pid) :-
    current_prolog_flag(pid, Pid).

		 /*******************************
		 *  FIRST QUERY, SCHEMA CHANGED *
		 *******************************/

%   bench_first_query(+Facts, +Samples): a store of Facts triples and
%   10 agents; the time of the first find on each model after a schema
%   change, with the schema tables left to that find (warm_schemas
%   off) and compiled ahead by the watcher thread (on).

bench_first_query(Facts, Samples) :-
    format("~nFirst query of a model after a schema change (~D triples, \c
            10 agents, in process)~n", [Facts]),
    oro_init([]),
    bench_world(Facts, Statements),
    bench_batches(Statements, 1000, Batches),
    forall(member(B, Batches), oro_add(myself, B)),
    numlist(1, 10, Ks),
    maplist([K, S]>>format(string(S), "agent~d rdf:type Human", [K]), Ks,
            Agents),
    oro_add(myself, Agents),
    oro_agents(_),                          % the agents' models made
    findall(M, oro_model(M), Models),
    Changes is max(1, Samples // 10),
    bench_header("triples"),
    forall(member(Warm, [false, true]),
           first_query_row(Warm, Facts, Models, Changes)),
    set_setting(oro_events:warm_schemas, true),
    oro_reset.

first_query_row(Warm, Facts, Models, Changes) :-
    set_setting(oro_events:warm_schemas, Warm),
    findall(Micros,
            ( between(1, Changes, I),
              format(string(Change), "Gadget~w_~d rdfs:subClassOf Artifact",
                     [Warm, I]),
              oro_add(myself, [Change]),
              oro_events_sync,
              (   Warm == true
              ->  forall(member(M, Models), warmed(M))
              ;   true
              ),
              member(Model, Models),
              bench_time(oro_find(Model, x, ["?x isOn furniture7"], _),
                         Micros)
            ),
            Times),
    format(atom(Name), "first find, warm_schemas ~w", [Warm]),
    bench_report(Name, Facts, Times).

%   warmed(+Model): the watcher thread has compiled Model's tables for
%   the current schema (10 s at most).

warmed(Model) :-
    get_time(T0),
    Deadline is T0 + 10,
    warmed(Model, Deadline).

warmed(Model, Deadline) :-
    (   oro_compiled_schema(Model, _)
    ->  true
    ;   get_time(Now),
        Now < Deadline
    ->  sleep(0.001),
        warmed(Model, Deadline)
    ;   throw(bench_failed(warmed(Model)))
    ).

		 /*******************************
		 *      addForAgent COST        *
		 *******************************/

bench_add_for_agent(Samples) :-
    format("~nAgent models over the socket (~d samples each)~n", [Samples]),
    bench_header('agents/n'),
    with_server([], Conn, _,
                forall(member(N, [1, 10, 100]),
                       add_for_agent_figures(Conn, N, Samples))).

add_for_agent_figures(Conn, N, Samples) :-
    bench_call(Conn, reset, []),
    numlist(1, N, Is),
    maplist(agent_statement, Is, Statements),
    get_time(T0),
    bench_call(Conn, add, [Statements]),
    wait_agents(Conn, N, 30),
    get_time(T1),
    Create is (T1 - T0) * 1.0e6 / N,
    row('create an agent model (each)', N, Create, -, 1.0e6/Create),
    bench_measure(N, I,
                  bench_call(Conn, findForAgent, [Agent, x, ['ag1 isOn ?x']]),
                  format(atom(Agent), 'ag~d', [I]),
                  First),
    report('first findForAgent in a model', N, First),
    bench_measure(Samples, I,
                  bench_call(Conn, addForAgent, [Agent, [S]]),
                  ( K is 1 + I mod N,
                    format(atom(Agent), 'ag~d', [K]),
                    format(atom(S), 'thing~d isOn table~d', [I, K])
                  ),
                  AddFor),
    report('addForAgent 1 statement', N, AddFor),
    bench_measure(Samples, I,
                  bench_call(Conn, findForAgent, [Agent, x, [P]]),
                  ( K is 1 + I mod N,
                    format(atom(Agent), 'ag~d', [K]),
                    format(atom(P), 'thing~d isOn ?x', [I])
                  ),
                  FindFor),
    report('findForAgent 1 pattern, 1 answer', N, FindFor),
    bench_measure(Samples, I,
                  bench_call(Conn, add, [[S]]),
                  format(atom(S), 'robotthing~d isOn table1', [I]),
                  Add),
    report('add 1 statement (robot model)', N, Add).

agent_statement(I, S) :-
    format(atom(S), 'ag~d rdf:type Agent', [I]).

%   wait_agents(+Conn, +Count, +Seconds): poll listAgents until it
%   lists Count agents agN.

wait_agents(Conn, Count, Seconds) :-
    get_time(Now),
    Deadline is Now + Seconds,
    wait_agents_(Conn, Count, Deadline).

wait_agents_(Conn, Count, Deadline) :-
    bench_call(Conn, listAgents, [], Value),
    agents_listed(Value, N),
    (   N >= Count
    ->  true
    ;   get_time(Now),
        Now < Deadline
    ->  sleep(0.005),
        wait_agents_(Conn, Count, Deadline)
    ;   throw(bench_failed(listAgents, timeout(N, Count)))
    ).

%   agents_listed(+Value, -N): the number of `agN` names listAgents
%   gave.

agents_listed(Value, N) :-
    atom_string(Atom, Value),
    atom_json_term(Atom, List, [value_string_as(atom)]),
    aggregate_all(count, ( member(Name, List),
                           sub_atom(Name, 0, _, _, ag)
                         ), N).

		 /*******************************
		 *      MEMORY PER AGENT        *
		 *******************************/

bench_memory_per_agent(N) :-
    format("~nMemory per agent model (~d agents created)~n", [N]),
    format("~w~t~34|~w~t~16+~w~t~16+~w~n",
           [where, 'RSS before', 'RSS after', 'per agent']),
    % In process.
    oro_init([]),
    garbage_collect,
    self_pid(Self),
    rss_kb(Self, Before),
    rdf_statistics(triples(TBefore)),
    rdf_statistics(graphs(GBefore)),
    numlist(1, N, Is),
    maplist(agent_statement, Is, Statements),
    oro_add(myself, Statements),
    oro_events_sync,
    oro_agents(Names),
    length(Names, Count),
    garbage_collect,
    rss_kb(Self, After),
    rdf_statistics(triples(TAfter)),
    rdf_statistics(graphs(GAfter)),
    PerAgent is (After - Before) / N,
    Triples is (TAfter - TBefore - N) / N,
    Graphs is (GAfter - GBefore) / N,
    memory_row('in process', Before, After, PerAgent),
    format("   (~d models listed; ~1f triples and ~1f graphs per agent \c
            model beside its rdf:type)~n", [Count, Triples, Graphs]),
    % The server process.
    with_server([], Conn, Pid,
                ( bench_call(Conn, stats, []),
                  rss_kb(Pid, SBefore),
                  bench_call(Conn, add, [Statements]),
                  wait_agents(Conn, N, 30),
                  rss_kb(Pid, SAfter),
                  SPerAgent is (SAfter - SBefore) / N,
                  memory_row('server process', SBefore, SAfter, SPerAgent)
                )).

memory_row(Where, Before, After, PerAgent) :-
    format("~w~t~34|~d kB~t~16+~d kB~t~16+~1f kB~n",
           [Where, Before, After, PerAgent]),
    flush_output.

		 /*******************************
		 *          FORGETTING          *
		 *******************************/

bench_forgetting(Facts, TimeBase, Checkers) :-
    Lifetime is 10 * TimeBase,
    format("~nForgetting ~D SHORTTERM facts added at once \c
            (time base ~d ms: lifetime ~d ms)~n", [Facts, TimeBase, Lifetime]),
    forget_in_process(Facts, TimeBase),
    forget_socket(Facts, TimeBase, Checkers).

fact_statements(Facts, Statements) :-
    findall(S, ( between(1, Facts, I),
                 format(atom(S), 'fact~d benchP benchO', [I])
               ), Statements).

%   In process: the deadline is known exactly (oro_memory_deadlines/2).

forget_in_process(Facts, TimeBase) :-
    oro_init([time_base(TimeBase)]),
    oro_add(myself, ["keeper benchP benchO"]),
    fact_statements(Facts, Statements),
    get_time(T0),
    oro_add(myself, Statements, shortterm),
    get_time(T1),
    oro_memory_deadlines(myself, [D0-_-_|_]),
    Deadline is D0 / 1000,
    AddRate is Facts / (T1 - T0),
    format("in process: add ~D SHORTTERM facts in ~3f s (~0f/s); \c
            deadline ~3f s after the add returned~n",
           [Facts, T1-T0, AddRate, Deadline-T1]),
    (   Deadline =< T1
    ->  format("   the facts expired while being added: use a larger \c
                --time-base~n")
    ;   true
    ),
    message_queue_create(Queue),
    flag(bench_stop, _, 0),
    thread_create(in_process_checker(Queue), Checker, []),
    scheduler_cpu(Cpu0),
    wait_gone_in_process(Facts, 30, Gone),
    scheduler_cpu(Cpu1),
    flag(bench_stop, _, 1),
    thread_join(Checker, _),
    thread_get_message(Queue, latencies(Latencies)),
    message_queue_destroy(Queue),
    Forget is Gone - Deadline,
    Cpu is Cpu1 - Cpu0,
    format("   all gone ~3f s after the deadline (~0f facts/s); \c
            scheduler CPU ~3f s (~1f us/fact)~n",
           [Forget, Facts / max(0.000001, Forget), Cpu, Cpu * 1.0e6 / Facts]),
    window_report('in-process check', Latencies, Deadline, Gone),
    oro_events_sync.

wait_gone_in_process(Facts, Seconds, Gone) :-
    format(string(First), "fact1 benchP benchO", []),
    format(string(Last), "fact~d benchP benchO", [Facts]),
    get_time(Now),
    Deadline is Now + Seconds,
    wait_gone_in_process_(First, Last, Deadline, Gone).

wait_gone_in_process_(First, Last, Deadline, Gone) :-
    (   \+ oro_check(myself, [First]),
        \+ oro_check(myself, [Last])
    ->  get_time(Gone)
    ;   get_time(Now),
        Now < Deadline
    ->  sleep(0.001),
        wait_gone_in_process_(First, Last, Deadline, Gone)
    ;   throw(bench_failed(forgetting, timeout))
    ).

in_process_checker(Queue) :-
    in_process_checks([], Latencies),
    thread_send_message(Queue, latencies(Latencies)).

in_process_checks(L0, L) :-
    (   flag(bench_stop, 1, 1)
    ->  L = L0
    ;   get_time(T0),
        ignore(oro_check(myself, ["keeper benchP benchO"])),
        get_time(T1),
        Micros is (T1 - T0) * 1.0e6,
        sleep(0.001),
        in_process_checks([T0-Micros|L0], L)
    ).

%   Over the socket: the server runs in this process (oro_server_start/2)
%   so that the deadline is known exactly; the clients are threads of
%   their own, each with its connection.

forget_socket(Facts, TimeBase, Checkers) :-
    setup_call_cleanup(
        oro_server_start([port(0), time_base(TimeBase)], Server),
        ( oro_server_port(Server, Port),
          bench_with_connection(Port, Conn,
                                forget_socket_(Conn, Port, Facts, Checkers))
        ),
        oro_server_stop(Server)).

forget_socket_(Conn, Port, Facts, Checkers) :-
    bench_call(Conn, add, [["keeper benchP benchO"]]),
    fact_statements(Facts, Statements),
    get_time(T0),
    bench_call(Conn, add, [Statements, 'SHORTTERM']),
    get_time(T1),
    oro_memory_deadlines(myself, [D0-_-_|_]),
    Deadline is D0 / 1000,
    format("socket (server in this process): add ~D SHORTTERM facts in \c
            one request in ~3f s (~0f/s); deadline ~3f s after the reply~n",
           [Facts, T1-T0, Facts/(T1-T0), Deadline-T1]),
    message_queue_create(Queue),
    flag(bench_stop, _, 0),
    length(Threads, Checkers),
    maplist(start_socket_checker(Port, Queue), Threads),
    format(atom(Last), 'fact~d benchP benchO', [Facts]),
    wait_gone_socket(Conn, ['fact1 benchP benchO', Last], 60, Gone),
    flag(bench_stop, _, 1),
    maplist(thread_join, Threads),
    findall(L, ( between(1, Checkers, _),
                 thread_get_message(Queue, latencies(L))
               ), Ls),
    append(Ls, Latencies),
    message_queue_destroy(Queue),
    Forget is Gone - Deadline,
    format("   all gone ~3f s after the deadline (~0f facts/s), seen over \c
            the socket; ~d concurrent check clients~n",
           [Forget, Facts / max(0.000001, Forget), Checkers]),
    window_report('socket check', Latencies, Deadline, Gone),
    oro_events_sync.

start_socket_checker(Port, Queue, Thread) :-
    thread_create(socket_checker(Port, Queue), Thread, []).

socket_checker(Port, Queue) :-
    bench_with_connection(Port, Conn,
                          socket_checks(Conn, [], Latencies)),
    thread_send_message(Queue, latencies(Latencies)).

socket_checks(Conn, L0, L) :-
    (   flag(bench_stop, 1, 1)
    ->  L = L0
    ;   get_time(T0),
        bench_call(Conn, check, [['keeper benchP benchO']]),
        get_time(T1),
        Micros is (T1 - T0) * 1.0e6,
        sleep(0.001),
        socket_checks(Conn, [T0-Micros|L0], L)
    ).

%   wait_gone_socket(+Conn, +Statements, +Seconds, -Gone): poll each
%   statement with check until all are false.

wait_gone_socket(Conn, Statements, Seconds, Gone) :-
    get_time(Now),
    Deadline is Now + Seconds,
    wait_gone_socket_(Conn, Statements, Deadline, Gone).

wait_gone_socket_(Conn, Statements, Deadline, Gone) :-
    (   forall(member(S, Statements),
               bench_call(Conn, check, [[S]], "false"))
    ->  get_time(Gone)
    ;   get_time(Now),
        Now < Deadline
    ->  sleep(0.002),
        wait_gone_socket_(Conn, Statements, Deadline, Gone)
    ;   throw(bench_failed(forgetting, timeout))
    ).

%   window_report(+Name, +Latencies, +Deadline, +End): check latencies
%   (Start-Micros) before the deadline and from the deadline to End.

window_report(Name, Latencies, Deadline, End) :-
    bench_header('agents/n'),
    partition(before(Deadline), Latencies, Before, Rest),
    include(before(End), Rest, During),
    pairs_values_(Before, B),
    pairs_values_(During, D),
    atom_concat(Name, ' before deadline', N1),
    atom_concat(Name, ' while forgetting', N2),
    report_or_none(N1, B),
    report_or_none(N2, D).

before(Time, Start-_) :-
    Start < Time.

pairs_values_(Pairs, Values) :-
    findall(V, member(_-V, Pairs), Values).

report_or_none(Name, []) :-
    !,
    format("~w~t~34|(no sample)~n", [Name]).
report_or_none(Name, Times) :-
    length(Times, N),
    report(Name, N, Times).

		 /*******************************
		 *   FORGETTING, SPREAD OUT     *
		 *******************************/

%   bench_forgetting_spread(+Facts, +Seconds, +Batch, +TimeBase): in
%   process.  The deadlines are read once all facts are added (before
%   the first one passes); a watcher thread (this one) then waits for
%   each fact to go, in deadline order, sleeping until shortly before
%   its deadline and then polling every 0.5 ms.

bench_forgetting_spread(Facts, Seconds, Batch, TimeBase) :-
    Lifetime is 10 * TimeBase,
    Batches is max(1, ceiling(Facts / Batch)),
    format("~nForgetting ~D SHORTTERM facts added over ~w s, ~D batches of \c
            ~d (time base ~d ms: lifetime ~d ms)~n",
           [Facts, Seconds, Batches, Batch, TimeBase, Lifetime]),
    oro_init([time_base(TimeBase)]),
    oro_add(myself, ["keeper benchP benchO"]),
    oro_memory_sync,
    scheduler_cpu(CpuA0),
    get_time(T0),
    spread_adds(0, Batches, Batch, Facts, T0, Seconds),
    get_time(T1),
    scheduler_cpu(CpuA1),
    oro_memory_deadlines(myself, Deadlines),
    length(Deadlines, Pending),
    distinct_deadlines(Deadlines, Distinct),
    format("in process: ~D facts added in ~3f s (~0f/s); ~D deadlines \c
            (~D distinct) pending when the adds returned; scheduler CPU \c
            during the adds ~3f s~n",
           [Facts, T1-T0, Facts/(T1-T0), Pending, Distinct, CpuA1-CpuA0]),
    (   Pending =\= Facts
    ->  format("   some facts expired while being added: use a larger \c
                --time-base or a smaller --spread-seconds~n")
    ;   true
    ),
    Deadlines = [First-_-_|_],
    last(Deadlines, LastD-_-_),
    FirstS is First / 1000,
    sleep_until(FirstS - 0.05),
    scheduler_cpu(Cpu0),
    watch_gone(Deadlines, 60, [], Lateness, Gone),
    scheduler_cpu(Cpu1),
    Cpu is Cpu1 - Cpu0,
    Window is Gone - FirstS,
    format("   expiry from the first deadline until the last fact was \c
            seen gone: ~3f s (deadlines spread over ~3f s)~n",
           [Window, (LastD - First) / 1000]),
    format("   scheduler CPU during expiry ~3f s (~1f us/fact, ~1f% of \c
            one core)~n",
           [Cpu, Cpu * 1.0e6 / max(1, Pending),
            100 * Cpu / max(0.000001, Window)]),
    Lateness = [LastLate|_],
    bench_stats(Lateness, Stats),
    format("   lateness (deadline -> seen gone, ~D facts): median ~3f ms, \c
            p99 ~3f ms, max ~3f ms; last fact ~3f ms~n",
           [Stats.n, Stats.median, Stats.p99, Stats.max, LastLate]),
    oro_events_sync.

spread_adds(I, Batches, _, _, _, _) :-
    I >= Batches,
    !.
spread_adds(I, Batches, Batch, Facts, T0, Seconds) :-
    sleep_until(T0 + I * Seconds / Batches),
    From is I * Batch + 1,
    To is min(Facts, From + Batch - 1),
    findall(S, ( between(From, To, K),
                 format(atom(S), 'sfact~d benchP benchO', [K])
               ), Statements),
    oro_add(myself, Statements, shortterm),
    I1 is I + 1,
    spread_adds(I1, Batches, Batch, Facts, T0, Seconds).

sleep_until(Time) :-
    get_time(Now),
    Wait is Time - Now,
    (   Wait > 0
    ->  sleep(Wait)
    ;   true
    ).

distinct_deadlines(Deadlines, N) :-
    findall(D, member(D-_-_, Deadlines), Ds0),
    sort(Ds0, Ds),
    length(Ds, N).

%   watch_gone(+Deadlines, +MaxSeconds, +Acc, -Lateness, -Gone):
%   Lateness (ms, the last fact's first) of each fact of Deadlines
%   (Deadline-rdf(S,P,O)-Profile, earliest first); Gone is when the last
%   one was seen gone.

watch_gone(Deadlines, MaxSeconds, Acc, Lateness, Gone) :-
    get_time(Now),
    Stop is Now + MaxSeconds,
    watch_gone_(Deadlines, Stop, Acc, Lateness, Now, Gone).

watch_gone_([], _, Lateness, Lateness, Gone, Gone).
watch_gone_([D-rdf(S, P, O)-_|Rest], Stop, Acc, Lateness, Gone0, Gone) :-
    (   \+ rdf(S, P, O)
    ->  get_time(Now),
        Late is Now * 1000 - D,
        watch_gone_(Rest, Stop, [Late|Acc], Lateness, Now, Gone)
    ;   get_time(Now),
        Now > Stop
    ->  throw(bench_failed(forgetting_spread, timeout))
    ;   sleep_until(D / 1000 - 0.002),
        sleep(0.0005),
        watch_gone_([D-rdf(S, P, O)-_|Rest], Stop, Acc, Lateness, Gone0,
                    Gone)
    ).

%   scheduler_cpu(-Seconds): the CPU time used so far by the memory
%   scheduler thread (oro_memory), from /proc (thread_statistics/3 may
%   not look at other threads).

scheduler_cpu(Seconds) :-
    (   catch(thread_property(oro_memory, system_thread_id(Tid)), _, fail)
    ->  format(atom(File), '/proc/self/task/~w/schedstat', [Tid]),
        read_file_to_string(File, Text, []),
        split_string(Text, " \n", " \n", [Ns|_]),
        number_string(N, Ns),
        Seconds is N / 1.0e9
    ;   Seconds = 0
    ).

		 /*******************************
		 *          MEASURING           *
		 *******************************/

%   Times in the tables switch to milliseconds from 10 ms on.

report(Name, Size, Times) :-
    bench_report(Name, Size, Times, [units(auto)]).

row(Name, Size, Median, P99, PerSecond) :-
    bench_row(Name, Size, Median, P99, PerSecond, [units(auto)]).
