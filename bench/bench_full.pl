/*  oro full benchmark (issue #9): every figure of the issue in one run,
    each beside its floor.

        swipl bench/bench_full.pl [--sizes=10000,100000,1000000]
                                  [--samples=300] [--budget=15]
                                  [--json=bench/results.json]
                                  [--log=../shared/workloads/robot-session-2011.log]
                                  [--pin=CPU]

    For each size, the same synthetic robot world is first loaded in
    this process with library(oro) (oro_init/1, oro_add/2), where
    check (asserted, inferred type, inferred property) and find with 1
    to 3 patterns are measured with oro_check/2 and oro_find/4; then a server
    child process (server/oro_server.pl --port=0) loads it over the
    socket, and one connection measures add 1, add a batch of 100,
    update, remove (of what add 1 added), check (asserted, inferred
    type, inferred property), find with 1 to 3 patterns, lookup,
    getInfos, the agents' findForAgent and addForAgent, 8 concurrent
    clients, the latency of a NEW_INSTANCE event with 1,000 watchers
    registered and, last, the rate of adds of 100 statements with two
    requests in flight on one connection, and with two clients adding
    at once, each one batch at a time.  Median, p99 and maximum of
    each, the server's memory (VmRSS after the load, VmHWM at the
    end).

    The floors, measured in the same run: an echo server with oro's
    framing and none of its work (bench_common:bench_echo_start/2, run
    as a child process of this script with --echo; re-measured before
    each size's figures and before the replay, as the machine is
    noisy), raw rdf_assert/4 and bound rdf/3 in this process (before
    library(oro) starts), and a bare `swipl -g halt` for the startup.
    Every figure is printed with its ratio to its floor: the socket
    figures to the echo round trip, the in-process ones to one rdf/3
    probe, the loads to rdf_assert/4, the replay to as many echo round
    trips as it sends requests.  Below the table, rdf_db's part of each
    in-process check and find: the index lookups one call makes
    (rdf_statistics/1), and the call's median shared among them, beside
    one rdf/3 probe.

    Also: the startup with the largest world's robot part (at least
    that many triples) written as Turtle and given with
    --ontology=FILE (and, as its floor, rdf_load/2 of the same file in
    this process, done first, while no library(oro) monitor watches
    the store); the replay of the robot session of 2011 (all requests,
    each client thread on its own connection, in log order, no sleeps)
    on a fresh server with the robot id of that experiment; startup to
    listening of the server with the bundled ontology; the 1M/100k
    ratios; the targets with PASS/MISS.

    --pin=CPU runs this process and every process it starts on that
    one CPU (see bench_common:bench_pin_to_cpu/1): the socket figures
    and their echo floor are then measured with the same placement,
    which the scheduler does not promise otherwise.  Throughput (bulk
    add, 8 clients) is lower there, as the client and the server take
    turns on one core.

    A table on stdout, progress on stderr, and everything in the JSON
    file (default bench/results.json): the machine line, the floors,
    each size's table rows, the targets with their verdicts, and the
    report as printed (`report`, one string a line).  --budget bounds
    the seconds spent sampling one operation (at least 20 samples are
    taken).
*/

:- prolog_load_context(directory, Dir),
   asserta(user:file_search_path(oro_bench, Dir)),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)).

:- use_module(library(semweb/rdf_db)).
:- use_module(library(semweb/turtle)).
:- use_module(library(process)).
:- use_module(library(readutil)).
:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(aggregate)).
:- use_module(library(pairs)).
:- use_module(library(http/json)).
:- use_module(library(main), [argv_options/3]).
:- use_module(library(oro)).
:- use_module(bench_common).

%   main/0 runs only when this file is the script swipl was started with,
%   so that its predicates can be loaded and tried one by one.

:- prolog_load_context(file, File),
   (   current_prolog_flag(associated_file, File)
   ->  initialization(main, main)
   ;   true
   ).

opt_type(sizes, sizes, term).
opt_type(samples, samples, nonneg).
opt_type(budget, budget, nonneg).
opt_type(json, json, atom).
opt_type(log, log, atom).
opt_type(echo, echo, boolean).
opt_type(pin, pin, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    (   option(echo(true), Options)
    ->  echo_main
    ;   bench(Options)
    ).

%   echo_main: the echo server as a child process: print its port, then
%   serve until SIGTERM or SIGINT.  As in the server, the main thread
%   handles both by halting (SIGINT is the one that cannot be lost:
%   see bench_common:bench_stop_process/1).

echo_main :-
    bench_echo_start(0, Echo),
    on_signal(term, _, echo_signal),
    on_signal(int, _, echo_signal),
    format("echo listening on 127.0.0.1:~w~n", [Echo.port]),
    flush_output,
    thread_get_message(echo_stop),
    halt(0).

echo_signal(_Signal) :-
    thread_send_message(main, echo_stop).

		 /*******************************
		 *            THE RUN           *
		 *******************************/

bench(Options) :-
    bench_list_option(sizes(Sizes), Options, [10000, 100000, 1000000]),
    option(samples(Samples), Options, 300),
    option(budget(Budget), Options, 15),
    absolute_file_name(oro_bench('results.json'), DefaultJSON),
    option(json(JSON), Options, DefaultJSON),
    absolute_file_name(oro_bench('../../shared/workloads/robot-session-2011.log'),
                       DefaultLog),
    option(log(Log), Options, DefaultLog),
    get_time(Start),
    nb_setval(bench_start, Start),
    retractall(said(_)),
    (   option(pin(CPU), Options)
    ->  bench_pin_to_cpu(CPU),
        Placement = cpu(CPU)
    ;   Placement = free
    ),
    machine(Sizes, Samples, Budget, Placement, Machine),
    Params = params{samples:Samples, budget:Budget},
    in_process_floors(Floors),
    max_list(Sizes, Largest),
    turtle_figures(Largest, Turtle),
    self_script(Self),
    bench_with_script(Self, ['--echo'], EchoPort, _,
                      ( maplist(size_figures(EchoPort, Params, Floors), Sizes, PerSize),
                        replay_figures(Log, EchoPort, Params, Replay)
                      )),
    startup_figures(Startup),
    scaling(PerSize, Scaling),
    targets(PerSize, Startup, Turtle, Replay, Scaling, Targets),
    get_time(End),
    Total is End - Start,
    say("~nWhole run: ~1f s~n", [Total]),
    say("JSON: ~w~n", [JSON]),
    report(Report),
    Results = results{machine:Machine, params:Params.put(sizes, Sizes),
                      floors:Floors, sizes:PerSize, startup:Startup,
                      turtle:Turtle, replay:Replay, scaling:Scaling,
                      targets:Targets, seconds:Total, report:Report},
    write_json(JSON, Results).

self_script(File) :-
    absolute_file_name(oro_bench('bench_full.pl'), File, [access(read)]).

%   machine(+Sizes, +Samples, +Budget, +Placement, -Machine): print the
%   machine line (bench_common:bench_machine/0) and the run's
%   parameters; Machine holds both lines as printed and their parts.

machine(Sizes, Samples, Budget, Placement,
        machine{line:Line, run_line:RunLine, prolog:V, cpu:CPU, cores:Cores,
                date:Date, placement:PlacementText}) :-
    with_output_to(string(Line0), bench_machine),
    split_string(Line0, "", "\n", [Line]),
    say("~w~n", [Line]),
    current_prolog_flag(version, V),
    catch(( read_file_to_string('/proc/cpuinfo', Info, []),
            sub_string(Info, B, _, _, "model name"),
            sub_string(Info, B, 80, _, L0),
            split_string(L0, "\n", "", [CPULine|_]),
            split_string(CPULine, ":", " \t", [_, CPU])
          ), _, CPU = "unknown cpu"),
    current_prolog_flag(cpu_count, Cores),
    get_time(Now),
    format_time(string(Date), '%F %T', Now),
    placement_text(Placement, PlacementText),
    format(string(RunLine), "~d cores; ~w; sizes ~w, ~d samples, budget ~d s an operation; ~w",
           [Cores, Date, Sizes, Samples, Budget, PlacementText]),
    say("~w~n", [RunLine]).

placement_text(free, "processes placed by the scheduler").
placement_text(cpu(CPU), Text) :-
    format(string(Text), "every process on CPU ~d (--pin)", [CPU]).

%   say(+Format, +Args): print on stdout (flushed) and keep the text
%   for the report in the JSON file.  report(-Lines): what say/2
%   printed, one string a line.

:- dynamic said/1.

say(Format, Args) :-
    format(string(Text), Format, Args),
    write(Text),
    flush_output,
    assertz(said(Text)).

report(Lines) :-
    findall(T, said(T), Texts),
    atomic_list_concat(Texts, Whole),
    split_string(Whole, "\n", "", Lines0),
    (   append(Lines, [""], Lines0)
    ->  true
    ;   Lines = Lines0
    ).

%   progress(+Format, +Args): a line on stderr, with the seconds since
%   the start.

progress(Format, Args) :-
    nb_getval(bench_start, Start),
    get_time(Now),
    T is Now - Start,
    format(user_error, "[~1f s] ", [T]),
    format(user_error, Format, Args),
    nl(user_error).

		 /*******************************
		 *       IN-PROCESS FLOORS      *
		 *******************************/

%   in_process_floors(-Floors): rdf_assert/4 of 100,000 triples shaped
%   like the world's into an empty graph (default hash tables, as the
%   server has), and bound rdf/3 probes on them; rdf_probe_us is the
%   time of one probe, the floor of the in-process check and find.

in_process_floors(floors{rdf_assert_per_s:AssertRate, rdf_probe_per_s:ProbeRate,
                         rdf_probe_us:ProbeMicros, triples:N}) :-
    progress("floors in process: rdf_assert/4, rdf/3", []),
    N = 100000,
    Graph = bench_floor,
    P = 'http://kb.openrobots.org#isOn',
    findall(rdf(S, P, O),
            ( between(1, N, I),
              format(atom(S), 'http://kb.openrobots.org#floor_obj~d', [I]),
              F is I mod 5000,
              format(atom(O), 'http://kb.openrobots.org#floor_f~d', [F])
            ), Triples),
    get_time(T0),
    forall(member(rdf(S, P, O), Triples), rdf_assert(S, P, O, Graph)),
    get_time(T1),
    forall(member(rdf(S, P, O), Triples), rdf(S, P, O)),
    get_time(T2),
    rdf_unload_graph(Graph),
    AssertRate is N / (T1 - T0),
    ProbeRate is N / (T2 - T1),
    ProbeMicros is 1.0e6 / ProbeRate,
    say("~nFloors in this process (~D triples): rdf_assert/4 ~0f/s, \c
         bound rdf/3 ~0f/s (~3f us a probe)~n",
        [N, AssertRate, ProbeRate, ProbeMicros]).

		 /*******************************
		 *          ONE SIZE            *
		 *******************************/

%   size_figures(+EchoPort, +Params, +Floors, +Size, -Figures):
%   everything measured on a world of Size asserted triples: first in
%   this process, then on a server holding it.

size_figures(EchoPort, Params, Floors, Size, Figures) :-
    world(Size, World),
    in_process_figures(Params, Floors, World, InProcess),
    progress("size ~D: starting a server", [Size]),
    bench_with_server([], Port, Pid,
                      bench_with_connection(
                          Port, C,
                          server_figures(C, Port, Pid, EchoPort, Params,
                                         World, Figures0))),
    print_size(Figures0.put(_{in_process:InProcess, floors:Floors}), Figures).

server_figures(C, Port, Pid, EchoPort, Params, World, Figures) :-
    Size = World.size,
    load_world(socket(C), World, Load),
    bench_memory(Pid, Loaded),
    progress("size ~D: loaded ~D statements, RSS ~w kB", [Size, Load.statements, Loaded.rss_kb]),
    echo_floors(EchoPort, Params, World, Echo),
    operations(C, Params, World, Echo, Ops),
    concurrency(Port, EchoPort, Params, World, Concurrent),
    event_figures(C, Params, World, Events),
    pipelined_load(C, World, Pipelined),
    writers_load(Port, World, Writers),
    bench_memory(Pid, End),
    Figures = size{triples:Size, world:World.put(statements, Load.statements),
                   load:Load, memory_loaded:Loaded, memory_end:End,
                   echo:Echo, operations:Ops, concurrent:Concurrent,
                   events:Events, pipelined:Pipelined, writers:Writers}.

		 /*******************************
		 *          THE WORLD           *
		 *******************************/

%   world(+Size, -World): the parameters of a synthetic robot world of
%   about Size asserted triples.
%
%     - Objects objI, typed under the common-sense classes (Cup, Plate,
%       Bottle, Book, Box, Toy, VideoTape, Spoon, Knife, AudioTape: all
%       Artifacts, most Tableware); 4 triples each: the type, where it
%       is (`isOn furnitureF`, or for one in five `isIn` a box, itself
%       an object), hasColor, isVisible.
%     - Furniture furnitureF, one for 20 objects (about 16 objects on
%       each whatever the size, so a find's answer does not grow with
%       the world), typed (Table, Shelf, Cupboard, Chair, Sofa,
%       ArmChair), labelled (`"table 12"`) and `isIn roomR`, ten to a
%       room; rooms are typed (Kitchen, LivingRoom, Bedroom) and
%       labelled.
%     - 10 agents humanA (Human, so the server gives each a model of
%       its own) that the robot sees looking at objects; 2% of the
%       triples are their beliefs, added to their models with
%       addForAgent: where objects are (often not where the robot put
%       them) and whether they are visible.

world(Size, world{size:Size, objects:Objects, furniture:NF, rooms:NR,
                  agents:NA, beliefs:Beliefs}) :-
    NA = 10,
    Beliefs is Size // 50,
    Objects is max(100, round((Size - Beliefs) / 4.16)),
    NF is max(1, Objects // 20),
    NR is (NF + 9) // 10.

%   room_of(+F, -R): furniture F is in room R, ten to a room.

room_of(F, R) :-
    R is 1 + (F - 1) // 10.

%   unit_statements(+World, +I, -Statements): object I's statements,
%   with those of the furniture and room introduced with it.

unit_statements(W, I, Statements) :-
    object_statements(W, I, Objs),
    (   I mod 20 =:= 0,
        F is I // 20,
        F =< W.furniture
    ->  furniture_statements(F, Furn),
        (   F mod 10 =:= 1
        ->  room_of(F, R),
            room_statements(R, Room)
        ;   Room = []
        )
    ;   Furn = [],
        Room = []
    ),
    (   I =< W.agents
    ->  agent_statements(W, I, Agent)
    ;   Agent = []
    ),
    append([Agent, Objs, Furn, Room], Statements).

object_statements(W, I, [Type, Place, Color, Visible]) :-
    object_class(I, Class),
    format(string(Type), "obj~d rdf:type ~w", [I, Class]),
    placement(W, I, Where, Target),
    format(string(Place), "obj~d ~w ~w", [I, Where, Target]),
    color(I, C),
    format(string(Color), "obj~d hasColor ~w", [I, C]),
    visible(I, V),
    format(string(Visible), "obj~d isVisible ~w", [I, V]).

object_class(I, Class) :-
    K is I mod 10,
    nth0(K, ['Cup', 'Plate', 'Bottle', 'Book', 'Box', 'Toy', 'VideoTape',
             'Spoon', 'Knife', 'AudioTape'], Class).

%   placement(+World, +I, -Property, -Target): where object I is.  One
%   object in five is in a box (an object whose index is 4 mod 10), the
%   others are on a piece of furniture.

placement(W, I, Property, Target) :-
    (   I mod 5 =:= 0
    ->  Property = isIn,
        Boxes is max(1, W.objects // 10),
        K is 10 * (((I // 5) * 7) mod Boxes) + 4,
        format(atom(Target), 'obj~d', [K])
    ;   Property = isOn,
        furniture_of(W, I, F),
        format(atom(Target), 'furniture~d', [F])
    ).

furniture_of(W, I, F) :-
    F is 1 + (I * 31) mod W.furniture.

color(I, C) :-
    K is (I // 10) mod 6,
    nth0(K, [red, green, blue, yellow, black, white], C).

visible(I, V) :-
    (   I mod 3 =:= 0
    ->  V = false
    ;   V = true
    ).

furniture_statements(F, [Type, Room, Label]) :-
    K is F mod 6,
    nth0(K, ['Table', 'Shelf', 'Cupboard', 'Chair', 'Sofa', 'ArmChair'], Class),
    format(string(Type), "furniture~d rdf:type ~w", [F, Class]),
    room_of(F, R),
    format(string(Room), "furniture~d isIn room~d", [F, R]),
    downcase_atom(Class, Name),
    format(string(Label), "furniture~d rdfs:label \"~w ~d\"", [F, Name, F]).

room_statements(R, [Type, Label]) :-
    K is R mod 3,
    nth0(K, ['Kitchen', 'LivingRoom', 'Bedroom'], Class),
    format(string(Type), "room~d rdf:type ~w", [R, Class]),
    downcase_atom(Class, Name),
    format(string(Label), "room~d rdfs:label \"~w ~d\"", [R, Name, R]).

agent_statements(W, A, [Type, Looks]) :-
    format(string(Type), "human~d rdf:type Human", [A]),
    X is 1 + (A * 97) mod W.objects,
    format(string(Looks), "human~d looksAt obj~d", [A, X]).

%   The beliefs of agent A: Beliefs/Agents statements about objects,
%   alternately where the object is (another piece of furniture than
%   the robot's) and that it is not visible.

belief_statements(W, A, Statements) :-
    N is W.beliefs // W.agents,
    findall(S, ( between(1, N, K),
                 belief(W, A, K, S)
               ), Statements).

belief(W, A, K, S) :-
    belief_object(W, A, K, I),
    (   K mod 2 =:= 0
    ->  G is 1 + (I * 17) mod W.furniture,
        format(string(S), "obj~d isOn furniture~d", [I, G])
    ;   format(string(S), "obj~d isVisible false", [I])
    ).

belief_object(W, A, K, I) :-
    I is 1 + (K * W.agents + A) mod W.objects.

		 /*******************************
		 *          LOADING             *
		 *******************************/

%   load_world(+Via, +World, -Load): add the robot's world in batches
%   of 100 (timing each request), wait for the agents' models, add the
%   agents' beliefs to their models in batches of 100.  Via is
%   socket(Conn) (add and addForAgent requests) or `in_process`
%   (oro_add/2 in this process).

load_world(Via, W, load{statements:N, seconds:Seconds, per_s:Rate, batch:Batch,
                        robot_statements:NRobot, robot_per_s:RobotRate,
                        belief_statements:NBeliefs, belief_per_s:BeliefRate}) :-
    via_text(Via, Where),
    progress("size ~D: loading ~D objects ~w", [W.size, W.objects, Where]),
    load_robot(Via, W, 1, [], RobotTimes0),
    append(RobotTimes0, RobotTimes),
    pairs_keys_values(RobotTimes, RobotCounts, RobotMicros),
    sum_list(RobotCounts, NRobot),
    sum_list(RobotMicros, RobotSum),
    wait_agents(Via, W.agents, 60),
    numlist(1, W.agents, Agents),
    maplist(load_beliefs(Via, W), Agents, BeliefTimes0),
    append(BeliefTimes0, BeliefTimes),
    pairs_keys_values(BeliefTimes, BeliefCounts, BeliefMicros),
    sum_list(BeliefCounts, NBeliefs),
    sum_list(BeliefMicros, BeliefSum),
    N is NRobot + NBeliefs,
    Seconds is (RobotSum + BeliefSum) / 1.0e6,
    Rate is N / max(1.0e-6, Seconds),
    RobotRate is NRobot / max(1.0e-6, RobotSum / 1.0e6),
    BeliefRate is NBeliefs / max(1.0e-6, BeliefSum / 1.0e6),
    include(full_batch, RobotTimes, Full),
    pairs_values(Full, FullMicros),
    bench_stats(FullMicros, Batch).

full_batch(100-_).

%   pipelined_load(+Conn, +World, -Pipelined): the rate of adds of 100
%   statements when the client keeps two requests in flight, sending
%   the next one before it reads the reply to the previous (ORO-SPEC
%   lets a client pipeline; the server answers in order), so that the
%   client's work and the server's overlap as they would with a
%   perception module streaming its facts.  The statements are those of
%   5,000 objects after the world's (about 20,000), made beforehand;
%   measured last, after every other figure of the size.

pipelined_load(C, W, pipelined{statements:N, seconds:Seconds, per_s:Rate,
                               in_flight:InFlight}) :-
    InFlight = 2,
    progress("size ~D: pipelined adds", [W.size]),
    From is W.objects + 1,
    To is W.objects + 5000,
    objects_statements(W, From, To, Statements),
    length(Statements, N),
    bench_batches(Statements, 100, Batches),
    bench_time(pipeline(C, Batches, 0, InFlight), Micros),
    Seconds is Micros / 1.0e6,
    Rate is N / max(1.0e-6, Seconds).

%   objects_statements(+World, +From, +To, -Statements): the statements
%   of the objects From..To (object_statements/3), beyond the world's
%   own when From > World.objects.

objects_statements(W, From, To, Statements) :-
    findall(S, ( between(From, To, I),
                 object_statements(W, I, Ss),
                 member(S, Ss)
               ), Statements).

%   pipeline(+Conn, +Batches, +Sent, +InFlight): send Batches, never
%   more than InFlight unanswered, and read every reply.

pipeline(C, [Batch|Batches], Sent, InFlight) :-
    Sent < InFlight,
    !,
    bench_send(C, add, [Batch]),
    Sent1 is Sent + 1,
    pipeline(C, Batches, Sent1, InFlight).
pipeline(_, [], 0, _) :-
    !.
pipeline(C, Batches, Sent, InFlight) :-
    bench_receive(C, Reply, infinite),
    (   Reply = ok(_)
    ->  true
    ;   throw(bench_failed(add, pipelined, Reply))
    ),
    Sent1 is Sent - 1,
    pipeline(C, Batches, Sent1, InFlight).

%   writers_load(+Port, +World, -Writers): the rate of adds of 100
%   statements when two clients, each on its own connection, add at
%   the same time, each one batch at a time (as two perception modules
%   would): the server then parses one client's batch while it writes
%   the other's.  Each adds the statements of 2,500 objects after those
%   of pipelined_load/3, made beforehand; the time runs from the start
%   of both to the last reply.

writers_load(Port, W, writers{statements:N, seconds:Seconds, per_s:Rate,
                              clients:Clients}) :-
    Clients = 2,
    progress("size ~D: ~d clients adding", [W.size, Clients]),
    numlist(1, Clients, Ks),
    maplist(writer_batches(W), Ks, Work),
    aggregate_all(sum(Len), ( member(Bs, Work),
                              member(B, Bs),
                              length(B, Len)
                            ), N),
    bench_time(run_writers(Port, Work), Micros),
    Seconds is Micros / 1.0e6,
    Rate is N / max(1.0e-6, Seconds).

writer_batches(W, K, Batches) :-
    From is W.objects + 5001 + (K - 1) * 2500,
    To is From + 2499,
    objects_statements(W, From, To, Statements),
    bench_batches(Statements, 100, Batches).

%   run_writers(+Port, +Work): a thread a client, each connecting (a
%   fraction of a millisecond of the time) and adding its batches.

run_writers(Port, Work) :-
    maplist(start_writer(Port), Work, Ids),
    maplist(join_writer, Ids).

start_writer(Port, Batches, Id) :-
    thread_create(bench_with_connection(Port, C, add_batches(C, Batches)),
                  Id, []).

add_batches(C, Batches) :-
    forall(member(B, Batches), bench_call(C, add, [B])).

join_writer(Id) :-
    thread_join(Id, Status),
    (   Status == true
    ->  true
    ;   throw(bench_failed(add, writers, Status))
    ).

via_text(socket(_), "over the socket").
via_text(in_process, "in this process").

%   load_robot(+Via, +World, +From, +Acc, -Times): the objects from
%   From on, 2,500 at a time (the statements are made a block at a
%   time, outside the timed requests).  Times are Count-Micros of each
%   request, a list a block, in reverse order.

load_robot(Via, W, From, Acc, Times) :-
    (   From > W.objects
    ->  Times = Acc
    ;   To is min(W.objects, From + 2499),
        findall(S, ( between(From, To, I),
                     unit_statements(W, I, Ss),
                     member(S, Ss)
                   ), Statements),
        bench_batches(Statements, 100, Batches),
        maplist(load_batch(Via, myself), Batches, BlockTimes),
        (   (To // 2500) mod 40 =:= 0
        ->  progress("size ~D: ~D objects of ~D", [W.size, To, W.objects])
        ;   true
        ),
        Next is To + 1,
        load_robot(Via, W, Next, [BlockTimes|Acc], Times)
    ).

load_beliefs(Via, W, A, Times) :-
    belief_statements(W, A, Statements),
    bench_batches(Statements, 100, Batches),
    format(atom(Agent), 'human~d', [A]),
    maplist(load_batch(Via, Agent), Batches, Times).

%   load_batch(+Via, +Model, +Batch, -Timed): add Batch to Model (the
%   robot's, `myself`, or an agent's); Timed is Count-Micros.

load_batch(Via, Model, Batch, Count-Micros) :-
    length(Batch, Count),
    bench_time(add_batch(Via, Model, Batch), Micros).

add_batch(socket(C), myself, Batch) :-
    !,
    bench_call(C, add, [Batch]).
add_batch(socket(C), Agent, Batch) :-
    bench_call(C, addForAgent, [Agent, Batch]).
add_batch(in_process, Model, Batch) :-
    oro_add(Model, Batch).

%   wait_agents(+Via, +N, +Seconds): over the socket, poll listAgents
%   until it lists human1 ... humanN (their models are created after
%   the add that typed them has been answered); in this process, wait
%   until the changes made so far have been seen by the watcher that
%   creates them (a name of an agent being created waits for it anyway).

wait_agents(socket(C), N, Seconds) :-
    numlist(1, N, Is),
    maplist([I, A]>>format(atom(A), 'human~d', [I]), Is, Names),
    wait_listed(C, Names, Seconds).
wait_agents(in_process, _, _) :-
    oro_events_sync.

wait_listed(C, Names, Seconds) :-
    get_time(Now),
    Deadline is Now + Seconds,
    wait_listed_(C, Names, Deadline).

wait_listed_(C, Names, Deadline) :-
    call_ok(C, listAgents, [], Value),
    atom_string(Text, Value),
    atom_json_term(Text, Listed0, [value_string_as(atom)]),
    (   subtract(Names, Listed0, [])
    ->  true
    ;   get_time(Now),
        Now < Deadline
    ->  sleep(0.01),
        wait_listed_(C, Names, Deadline)
    ;   throw(bench_failed(listAgents, timeout(Names, Listed0)))
    ).

%   call_ok(+Conn, +Method, +Params[, -Value]): a request whose reply
%   must be ok, within two minutes.

call_ok(C, Method, Params) :-
    bench_call(C, Method, Params, _, 120).

call_ok(C, Method, Params, Value) :-
    bench_call(C, Method, Params, Value0, 120),
    Value = Value0.

%   expect(+Conn, +Method, +Params, +Check): a request whose reply must
%   be ok with a value satisfying Check: `true`, `nonempty` (a JSON
%   list that is not empty), `list` (a JSON list) or `any`.  A wrong
%   answer stops the run: a fast wrong server is no result.

expect(C, Method, Params, Check) :-
    call_ok(C, Method, Params, Value),
    (   expected(Check, Value)
    ->  true
    ;   throw(bench_wrong_answer(Method, Params, Value))
    ).

expected(any, _).
expected(true, "true").
expected(list, Value) :-
    sub_string(Value, 0, 1, _, "[").
expected(nonempty, Value) :-
    sub_string(Value, 0, 1, _, "["),
    Value \== "[]".

		 /*******************************
		 *         ECHO FLOORS          *
		 *******************************/

%   echo_floors(+EchoPort, +Params, +World, -Echo): the echo server's
%   round trip for a one-statement request and a 100-statement one,
%   right before a size's figures.

echo_floors(EchoPort, Params, W, echo{one:One, batch:Batch}) :-
    bench_with_connection(
        EchoPort, E,
        ( bench_measure(Params.samples, Params.budget, I,
                        bench_call(E, check, [[S]], "true"),
                        asserted_statement(W, I, S), T1),
          bench_measure(Params.samples, Params.budget, I,
                        bench_call(E, add, [B]),
                        bulk_batch(W, bulk, I, B), T100)
        )),
    bench_stats(T1, One),
    bench_stats(T100, Batch).

		 /*******************************
		 *          OPERATIONS          *
		 *******************************/

%   operations(+Conn, +Params, +World, +Echo, -Ops): each operation of
%   op/9, in order, measured by measure/7.  What an operation's
%   samples did is passed on to the later ones (Done, a dict): add 1
%   records the statements it added, which remove then takes away.

operations(C, Params, W, Echo, Ops) :-
    findall(Key, op(Key, _, _, C, W, _, _, _, _), Keys),
    foldl(operation(C, Params, W, Echo), Keys, Ops, done{}, _).

operation(C, Params, W, Echo, Key, Op, Done0, Done) :-
    once(op(Key, Label, FloorKey, C, W, Done0, I, Goal, Prepare)),
    progress("size ~D: ~w", [W.size, Label]),
    op_samples(Key, Params, Done0, N),
    measure(N, Params, I, Goal, Prepare, Samples, Stats),
    recorded(Key, Samples, Done0, Done),
    Floor = Echo.FloorKey,
    Ratio is Stats.median / Floor.median,
    (   FloorKey == batch
    ->  PerSecond is 100 * 1.0e6 / Stats.median
    ;   PerSecond is 1.0e6 / Stats.median
    ),
    Op = op{key:Key, label:Label, stats:Stats, floor:FloorKey,
            floor_median:Floor.median, ratio:Ratio, per_s:PerSecond}.

%   measure(+N, +Params, ?I, :Goal, :Prepare, -Samples, -Stats): up to
%   N samples of Goal within the budget (bench_measure/7, recording
%   each sample's Goal as it ran); Stats leave out the first 5 (first
%   use of an index, first compilation of a schema closure).

measure(N, Params, I, Goal, Prepare, Samples, Stats) :-
    bench_measure(N, Params.budget, I, Goal, Prepare, Goal, Samples),
    pairs_values(Samples, Times0),
    warmed_up(Times0, Times),
    bench_stats(Times, Stats).

warmed_up(Times0, Times) :-
    (   length(Warm, 5),
        append(Warm, Times, Times0),
        Times \== []
    ->  true
    ;   Times = Times0
    ).

%   op_samples(+Key, +Params, +Done, -N): how many samples to take, the
%   5 that warm up included; remove takes one for each statement add 1
%   added.

op_samples(remove, _, Done, N) :-
    !,
    length(Done.add_1, N).
op_samples(_, Params, _, N) :-
    N is Params.samples + 5.

%   recorded(+Key, +Samples, +Done0, -Done): add 1 records the
%   statements its requests added (each sample's Goal as it ran: only
%   those answered `ok` are there).

recorded(add_1, Samples, Done0, Done) :-
    !,
    findall(S, member(call_ok(_, add, [[S]])-_, Samples), Added),
    Done = Done0.put(add_1, Added).
recorded(_, _, Done, Done).

%   op(?Key, ?Label, ?Floor, +Conn, +World, +Done, ?I, -Goal, -Prepare):
%   an operation measured over the socket: sample I runs Prepare, then
%   times Goal.  Floor is the echo figure it is compared with (`one`
%   for a request of one statement, `batch` for 100).  Done is what the
%   operations before it recorded (recorded/4): remove takes away the
%   statements add 1 added, the Ith sample the Ith statement.

op(add_1, "add 1 statement", one, C, W, _, I,
   call_ok(C, add, [[S]]),
   extra_statement(W, I, S)).
op(add_100, "add a batch of 100", batch, C, W, _, I,
   call_ok(C, add, [B]),
   bulk_batch(W, bulk, I, B)).
op(add_100_quoted, "add a batch of 100, quoted as liboro sends it", batch,
   C, W, _, I,
   call_ok(C, add, [B]),
   ( bulk_batch(W, quoted, I, B0),
     bench_quoted(B0, B)
   )).
op(update, "update 1 (functional property)", one, C, W, _, I,
   call_ok(C, update, [[S]]),
   update_statement(W, I, S)).
op(remove, "remove 1 statement (one add 1 added)", one, C, _, Done, I,
   call_ok(C, remove, [[S]]),
   ( get_dict(add_1, Done, Added),
     nth1(I, Added, S)
   )).
op(check_asserted, "check, asserted", one, C, W, _, I,
   expect(C, check, [[S]], true),
   asserted_statement(W, I, S)).
op(check_type, "check, inferred type", one, C, W, _, I,
   expect(C, check, [[S]], true),
   inferred_type_statement(W, I, S)).
op(check_property, "check, inferred property (isAt)", one, C, W, _, I,
   expect(C, check, [[S]], true),
   inferred_property_statement(W, I, S)).
op(find_1, "find, 1 pattern (inferred property)", one, C, W, _, I,
   expect(C, find, ["o", [P]], nonempty),
   furniture_pattern(W, I, P)).
op(find_2, "find, 2 patterns (+ inferred type)", one, C, W, _, I,
   expect(C, find, ["o", [P, "?o rdf:type Tableware"]], list),
   furniture_pattern(W, I, P)).
op(find_3, "find, 3 patterns (room, furniture, type)", one, C, W, _, I,
   expect(C, find, ["o", ["?o isAt ?f", P, "?o rdf:type Tableware"]], list),
   room_pattern(W, I, P)).
op(lookup_label, "lookup, a label", one, C, W, _, I,
   expect(C, lookup, [T], nonempty),
   ( Tables is max(1, W.furniture // 6),
     F is 6 * (1 + I mod Tables),
     format(string(T), "\"table ~d\"", [F])
   )).
op(lookup_name, "lookup, a name", one, C, W, _, I,
   expect(C, lookup, [T], nonempty),
   ( sample_object(W, I, J),
     format(string(T), "obj~d", [J])
   )).
op(get_infos, "getInfos", one, C, W, _, I,
   expect(C, getInfos, [T], nonempty),
   ( sample_object(W, I, J),
     format(string(T), "obj~d", [J])
   )).
op(find_for_agent, "findForAgent, 1 pattern (inferred)", one, C, W, _, I,
   expect(C, findForAgent, [Agent, "x", [P]], nonempty),
   ( A is 1 + I mod W.agents,
     format(atom(Agent), 'human~d', [A]),
     K is 2 * (1 + I mod max(1, W.beliefs // W.agents // 2)),
     belief_object(W, A, K, J),
     format(string(P), "obj~d isAt ?x", [J])
   )).
op(add_for_agent, "addForAgent 1 statement", one, C, W, _, I,
   call_ok(C, addForAgent, [Agent, [S]]),
   ( A is 1 + I mod W.agents,
     format(atom(Agent), 'human~d', [A]),
     furniture_of(W, I, F),
     format(string(S), "belief~d isOn furniture~d", [I, F])
   )).

%   The samples' statements.

extra_statement(W, I, S) :-
    furniture_of(W, I, F),
    format(string(S), "extra~d isOn furniture~d", [I, F]).

%   bulk_batch(+World, +Prefix, +I, -Batch): the 100 statements of
%   sample I of the adds of 100, each object on one of 100 shelves of
%   their own (shelfK), which no find asks about.  (They were put on
%   the world's furniture 1..100, which the 610 batches of the two adds
%   of 100 left with some 626 objects each instead of 16: the finds
%   measured after them that asked about it, 9% of their samples, had
%   that many answers, and made the finds' p99.)

bulk_batch(_, Prefix, I, Batch) :-
    findall(S, ( between(1, 100, K),
                 format(string(S), "~w~d_~d isOn shelf~d", [Prefix, I, K, K])
               ), Batch).

%   sample_object(+World, +I, -J): the object of sample I, spread over
%   the world.

sample_object(W, I, J) :-
    J is 1 + (I * 7919) mod W.objects.

sample_furniture(W, I, F) :-
    F is 1 + (I * 7) mod W.furniture.

asserted_statement(W, I, S) :-
    sample_object(W, I, J),
    placement(W, J, Property, Target),
    format(string(S), "obj~d ~w ~w", [J, Property, Target]).

inferred_type_statement(W, I, S) :-
    sample_object(W, I, J),
    format(string(S), "obj~d rdf:type Artifact", [J]).

inferred_property_statement(W, I, S) :-
    sample_object(W, I, J),
    placement(W, J, _, Target),
    format(string(S), "obj~d isAt ~w", [J, Target]).

furniture_pattern(W, I, P) :-
    sample_furniture(W, I, F),
    format(string(P), "?o isAt furniture~d", [F]).

room_pattern(W, I, P) :-
    R is 1 + I mod W.rooms,
    format(string(P), "?f isIn room~d", [R]).

%   update: the opposite of the object's initial visibility.

update_statement(W, I, S) :-
    sample_object(W, I, J),
    visible(J, V0),
    (   V0 == true
    ->  V = false
    ;   V = true
    ),
    format(string(S), "obj~d isVisible ~w", [J, V]).

		 /*******************************
		 *          IN PROCESS          *
		 *******************************/

%   in_process_figures(+Params, +Floors, +World, -InProcess): the world
%   loaded in this process by library(oro) on a fresh store
%   (oro_init/1 with the server's defaults), the robot's part and the
%   agents' beliefs in batches of 100 as over the socket; then check
%   and find as of in_process_op/6, the same samples as the socket's,
%   each beside one bound rdf/3 probe (Floors.rdf_probe_us).  The store
%   is emptied of the world afterwards (oro_reset/0).

in_process_figures(Params, Floors, W, in_process{load:Load, operations:Ops,
                                                  probe_us:ProbeMicros}) :-
    oro_init([]),
    load_world(in_process, W, Load),
    ProbeMicros = Floors.rdf_probe_us,
    findall(Key, in_process_op(Key, _, W, _, _, _), Keys),
    maplist(in_process_operation(Params, W, ProbeMicros), Keys, Ops),
    oro_reset.

in_process_operation(Params, W, ProbeMicros, Key, Op) :-
    once(in_process_op(Key, Label, W, I, Goal, Prepare)),
    progress("size ~D: in process, ~w", [W.size, Label]),
    N is Params.samples + 5,
    rdf_lookups(Before),
    measure(N, Params, I, Goal, Prepare, Samples, Stats),
    rdf_lookups(After),
    length(Samples, Taken),
    Lookups is (After - Before) / max(1, Taken),
    Ratio is Stats.median / ProbeMicros,
    PerSecond is 1.0e6 / Stats.median,
    Op = op{key:Key, label:Label, stats:Stats, floor:rdf_probe,
            floor_median:ProbeMicros, ratio:Ratio, per_s:PerSecond,
            lookups:Lookups}.

%   rdf_lookups(-Count): the index lookups rdf_db has made in this
%   process so far, all indexes together (rdf_statistics/1).  An
%   operation's count is taken around its samples, while the world is
%   loaded and nothing else queries the store.

rdf_lookups(Count) :-
    aggregate_all(sum(C), rdf_statistics(lookup(_, C)), Count).

%   in_process_op(?Key, ?Label, +World, ?I, -Goal, -Prepare): as op/9,
%   calling library(oro) in this process (the predicates the server's
%   check and find call).  A wrong answer stops the run.

in_process_op(check_asserted, "check, asserted", W, I,
              in_process_check(S),
              asserted_statement(W, I, S)).
in_process_op(check_type, "check, inferred type", W, I,
              in_process_check(S),
              inferred_type_statement(W, I, S)).
in_process_op(check_property, "check, inferred property (isAt)", W, I,
              in_process_check(S),
              inferred_property_statement(W, I, S)).
in_process_op(find_1, "find, 1 pattern (inferred property)", W, I,
              in_process_find([P], nonempty),
              furniture_pattern(W, I, P)).
in_process_op(find_2, "find, 2 patterns (+ inferred type)", W, I,
              in_process_find([P, "?o rdf:type Tableware"], list),
              furniture_pattern(W, I, P)).
in_process_op(find_3, "find, 3 patterns (room, furniture, type)", W, I,
              in_process_find(["?o isAt ?f", P, "?o rdf:type Tableware"],
                              list),
              room_pattern(W, I, P)).

in_process_check(S) :-
    (   oro_check(myself, [S])
    ->  true
    ;   throw(bench_wrong_answer(oro_check, [S], false))
    ).

%   in_process_find(+Patterns, +Check): find ?o; Check is `nonempty`
%   (the answer must not be empty) or `list` (any answer), as expect/4's.

in_process_find(Patterns, Check) :-
    oro_find(myself, o, Patterns, Values),
    (   ( Check == list ; Values \== [] )
    ->  true
    ;   throw(bench_wrong_answer(oro_find, Patterns, Values))
    ).

		 /*******************************
		 *          CONCURRENCY         *
		 *******************************/

%   concurrency(+Port, +EchoPort, +Params, +World, -Figures): 8 clients,
%   each on its own connection, each sending up to `samples` requests
%   (a mix: check asserted, check inferred type, find 1 pattern, add 1)
%   as fast as they are answered; the same clients against the echo
%   server.

concurrency(Port, EchoPort, Params, W, concurrent{clients:N, server:Server, echo:Echo,
                                                   ratio:Ratio}) :-
    N = 8,
    progress("size ~D: ~d concurrent clients", [W.size, N]),
    clients(Port, N, Params, W, Server),
    clients(EchoPort, N, Params, W, Echo),
    Ratio is Echo.per_s / Server.per_s.

clients(Port, N, Params, W, result{requests:Count, seconds:Seconds, per_s:PerSecond,
                                   stats:Stats}) :-
    message_queue_create(Queue),
    get_time(Now),
    Deadline is Now + Params.budget + 60,
    numlist(1, N, Ks),
    maplist(start_client(Port, Queue, Params, W), Ks, Threads),
    maplist(ready(Queue, Deadline), Ks),
    get_time(T0),
    maplist([T]>>thread_send_message(T, go), Threads),
    maplist(client_result(Queue, Deadline), Ks, Results),
    maplist(thread_join, Threads),
    message_queue_destroy(Queue),
    (   memberchk(failed(E), Results)
    ->  throw(E)
    ;   true
    ),
    pairs_keys_values(Results, Ends, TimeLists),
    max_list(Ends, T1),
    append(TimeLists, Times),
    length(Times, Count),
    Seconds is T1 - T0,
    PerSecond is Count / Seconds,
    bench_stats(Times, Stats).

start_client(Port, Queue, Params, W, K, Thread) :-
    thread_create(client(Port, Queue, Params, W, K), Thread, []).

ready(Queue, Deadline, _) :-
    (   thread_get_message(Queue, ready(_), [deadline(Deadline)])
    ->  true
    ;   throw(bench_failed(clients, not_ready))
    ).

client_result(Queue, Deadline, _, Result) :-
    (   thread_get_message(Queue, done(Result), [deadline(Deadline)])
    ->  true
    ;   throw(bench_failed(clients, no_result))
    ).

client(Port, Queue, Params, W, K) :-
    (   catch(client_run(Port, Queue, Params, W, K, Result0), E,
              Result0 = failed(E))
    ->  Result = Result0
    ;   Result = failed(bench_failed(client, K))
    ),
    thread_send_message(Queue, done(Result)).

client_run(Port, Queue, Params, W, K, End-Times) :-
    bench_with_connection(
        Port, C,
        ( thread_send_message(Queue, ready(K)),
          thread_get_message(go),
          bench_measure(Params.samples, Params.budget, I,
                        bench_call(C, Method, Args, _, 120),
                        mix_request(W, K, I, Method, Args),
                        Times),
          get_time(End)
        )).

mix_request(W, K, I, Method, Params) :-
    Case is I mod 4,
    J is I * 8 + K,
    (   Case =:= 0
    ->  Method = check,
        asserted_statement(W, J, S),
        Params = [[S]]
    ;   Case =:= 1
    ->  Method = check,
        inferred_type_statement(W, J, S),
        Params = [[S]]
    ;   Case =:= 2
    ->  Method = find,
        furniture_pattern(W, J, P),
        Params = ["o", [P]]
    ;   Method = add,
        furniture_of(W, J, F),
        format(string(S), "client~d_~d isOn furniture~d", [K, I, F]),
        Params = [[S]]
    ).

		 /*******************************
		 *            EVENTS            *
		 *******************************/

%   event_figures(+Conn, +Params, +World, -Events): the latency of a
%   NEW_INSTANCE event (from sending the add that causes it to reading
%   the event) with 1,000 other NEW_INSTANCE watchers registered:
%
%     - `same`: the 1,000 watch `?o isOn furnitureK` (K = 1..1000),
%       the very predicate the measured changes use, so each change
%       re-evaluates all of them (the hard case, used by the target);
%     - `other`: the 1,000 watch `?o isIn container_K`, a predicate the
%       changes do not touch.
%
%   The measured watcher, `?o isOn bench_table`, is registered last.  A
%   sample whose event does not come within 5 s, or comes with another
%   content, is missed.

event_figures(C, Params, W, events{watchers:1000, same:Same, other:Other}) :-
    progress("size ~D: events, 1000 watchers on the changed predicate", [W.size]),
    watchers_latency(C, Params, "[?o isOn furniture~d]", same, Same),
    progress("size ~D: events, 1000 watchers on another predicate", [W.size]),
    watchers_latency(C, Params, "[?o isIn container_~d]", other, Other).

watchers_latency(C, Params, Format, Tag, result{register:Register, latency:Latency,
                                                 after_ok:AfterOk, missed:Missed}) :-
    findall(T, ( between(1, 1000, K),
                 format(string(P), Format, [K]),
                 bench_time(call_ok(C, registerEvent,
                                    ["NEW_INSTANCE", "ON_TRUE", "o", P]), T)
               ), RegTimes),
    bench_stats(RegTimes, Register),
    format(string(Table), "[?o isOn bench_table_~w]", [Tag]),
    call_ok(C, registerEvent, ["NEW_INSTANCE", "ON_TRUE", "o", Table], Id),
    get_time(Now),
    Deadline is Now + Params.budget,
    latencies(C, Id, Tag, 1, Params.samples, Deadline, Samples),
    findall(L, member(L-_, Samples), Latencies),
    findall(A, member(_-A, Samples), After),
    aggregate_all(count, member(missed(_), Samples), Missed),
    bench_stats(Latencies, Latency),
    bench_stats(After, AfterOk),
    call_ok(C, clearEvents, []).

latencies(C, Id, Tag, I, N, Deadline, Samples) :-
    (   I > N
    ->  Samples = []
    ;   I > 20,
        get_time(Now),
        Now > Deadline
    ->  Samples = []
    ;   latency(C, Id, Tag, I, Sample),
        Samples = [Sample|Rest],
        I1 is I + 1,
        latencies(C, Id, Tag, I1, N, Deadline, Rest)
    ).

latency(C, Id, Tag, I, Sample) :-
    format(atom(Obj), 'ev_~w_~d', [Tag, I]),
    format(string(Stmt), "[~w isOn bench_table_~w]", [Obj, Tag]),
    format(string(Expected), "[\"~w\"]", [Obj]),
    get_time(T0),
    bench_send(C, add, [Stmt]),
    bench_receive(C, Reply, 120),
    (   Reply = ok(_)
    ->  get_time(TOk),
        bench_receive(C, Event, 5),
        get_time(T1),
        (   Event = event(Id, Expected)
        ->  Latency is (T1 - T0) * 1.0e6,
            After is (T1 - TOk) * 1.0e6,
            Sample = Latency-After
        ;   Sample = missed(Event)
        )
    ;   Sample = missed(Reply)
    ).

		 /*******************************
		 *           STARTUP            *
		 *******************************/

%   startup_figures(-Startup): wall time from starting `swipl
%   server/oro_server.pl --port=0` to its listening line, 5 runs, beside
%   a bare `swipl -g halt`; the server's memory once listening.

startup_figures(startup{runs:5, stats:Stats, memory:Memory, floor:Floor, ratio:Ratio}) :-
    progress("startup to listening", []),
    findall(T-M, ( between(1, 5, _),
                   startup_time([], T, M)
                 ), Runs),
    pairs_keys_values(Runs, Times, [Memory|_]),
    bench_stats(Times, Stats),
    findall(T, ( between(1, 5, _),
                 bench_time(bare_swipl, T)
               ), FloorTimes),
    bench_stats(FloorTimes, Floor),
    Ratio is Stats.median / Floor.median,
    ms_text(Stats.median, Median),
    ms_text(Stats.max, Max),
    ms_text(Floor.median, FloorMedian),
    say("~nStartup to listening (5 runs): median ~w, max ~w; \c
         bare swipl -g halt ~w (~1fx); server RSS ~w kB~n",
        [Median, Max, FloorMedian, Ratio, Memory.rss_kb]).

%   startup_time(+Args, -Micros, -Memory): start the server with Args,
%   time until its listening line, read its memory, stop it.

startup_time(Args, Micros, Memory) :-
    bench_server_script(Server),
    get_time(T0),
    setup_call_cleanup(
        process_create(path(swipl), [Server, '--port=0'|Args],
                       [stdout(pipe(Out)), process(Pid)]),
        ( read_line_to_string(Out, Line),
          get_time(T1),
          (   string(Line),
              sub_string(Line, 0, _, _, "oro listening on")
          ->  true
          ;   throw(bench_failed(startup, Line))
          ),
          bench_memory(Pid, Memory)
        ),
        ( bench_stop_process(Pid),
          close(Out)
        )),
    Micros is (T1 - T0) * 1.0e6.

bare_swipl :-
    process_create(path(swipl), ['-g', halt], [process(Pid)]),
    process_wait(Pid, _).

		 /*******************************
		 *        TURTLE LOADING        *
		 *******************************/

%   turtle_figures(+Size, -Turtle): a robot world of at least Size
%   triples (turtle_world/2) written as Turtle to a temporary file; the
%   server's startup to listening with --ontology=FILE (one run), and
%   rdf_load/2 of the file in this process (its floor).  Triples is
%   what rdf_load/2 loaded, Written what was written.

turtle_figures(Size, turtle{size:Size, objects:Objects, written:Written,
                            triples:Triples, bytes:Bytes, startup_s:Startup,
                            load_s:Load, memory:Memory, floor_s:Floor,
                            ratio:Ratio}) :-
    turtle_world(Size, W),
    Objects = W.objects,
    progress("Turtle: writing a world of at least ~D triples (~D objects)",
             [Size, W.objects]),
    setup_call_cleanup(
        tmp_file_stream(File, Stream, [extension(ttl), encoding(utf8)]),
        write_turtle(Stream, W, Written),
        close(Stream)),
    call_cleanup(turtle_load(File, Triples, Bytes, Startup, Memory, Floor),
                 delete_file(File)),
    startup_baseline(Baseline),
    Load is Startup - Baseline,
    Ratio is Load / Floor,
    say("~nTurtle: ~D triples (~1f MB): server startup to listening \c
         ~2f s (~2f s beyond a plain startup), RSS ~w kB; rdf_load/2 \c
         in process ~2f s (~1fx)~n",
        [Triples, Bytes / 1048576, Startup, Load, Memory.rss_kb, Floor, Ratio]).

%   turtle_world(+Size, -World): the robot's part of a world (objects,
%   furniture, rooms, the agents' types) of at least Size triples.  A
%   Turtle file has no agents' models: the agents' beliefs of world/2
%   (2% of its triples) are made up for with more objects.

turtle_world(Size, W) :-
    world(Size, W0),
    Objects0 is max(100, ceiling(Size / 4.16)),
    turtle_world(Size, W0.put(beliefs, 0), Objects0, W).

turtle_world(Size, W0, Objects, W) :-
    NF is max(1, Objects // 20),
    NR is (NF + 9) // 10,
    W1 = W0.put(_{objects:Objects, furniture:NF, rooms:NR}),
    robot_triples(W1, N),
    (   N >= Size
    ->  W = W1
    ;   More is Objects + 1 + (Size - N) // 5,
        turtle_world(Size, W0, More, W)
    ).

%   robot_triples(+World, -N): the triples of unit_statements/3 over
%   all objects: 4 an object, 3 a piece of furniture, 2 a room, 2 an
%   agent.

robot_triples(W, N) :-
    N is 4 * W.objects + 3 * W.furniture + 2 * W.rooms
       + 2 * min(W.agents, W.objects).

turtle_load(File, Triples, Bytes, Startup, Memory, Floor) :-
    size_file(File, Bytes),
    progress("Turtle: server startup with --ontology (~D bytes)", [Bytes]),
    format(atom(Arg), '--ontology=~w', [File]),
    startup_time([Arg], Micros, Memory),
    Startup is Micros / 1.0e6,
    progress("Turtle: rdf_load/2 in this process", []),
    get_time(T0),
    rdf_load(File, [graph(bench_turtle), format(turtle), silent(true)]),
    get_time(T1),
    rdf_graph_property(bench_turtle, triples(Triples)),
    rdf_unload_graph(bench_turtle),
    Floor is T1 - T0.

%   startup_baseline(-Seconds): one plain startup, to subtract.

startup_baseline(Seconds) :-
    startup_time([], Micros, _),
    Seconds is Micros / 1.0e6.

%   write_turtle(+Out, +World, -Written): the robot's part of World
%   (unit_statements/3 of every object) as Turtle; Written is the number
%   of triples written.

write_turtle(Out, W, Written) :-
    format(Out, "@prefix : <http://kb.openrobots.org#> .~n\c
                 @prefix rdfs: <http://www.w3.org/2000/01/rdf-schema#> .~n~n", []),
    aggregate_all(count,
                  ( between(1, W.objects, I),
                    unit_statements(W, I, Statements),
                    member(S, Statements),
                    turtle_triple(Out, S)
                  ), Written).

%   turtle_triple(+Out, +Statement): one of the world's statements
%   (subject, predicate, object separated by single spaces; the object
%   a name, a boolean or a quoted string) as a Turtle triple.

turtle_triple(Out, Statement) :-
    sub_string(Statement, B1, 1, _, " "),
    !,
    sub_string(Statement, 0, B1, _, S),
    A1 is B1 + 1,
    sub_string(Statement, A1, _, 0, Rest),
    sub_string(Rest, B2, 1, _, " "),
    !,
    sub_string(Rest, 0, B2, _, P),
    A2 is B2 + 1,
    sub_string(Rest, A2, _, 0, O),
    turtle_predicate(P, TP),
    turtle_object(O, TO),
    format(Out, ":~w ~w ~w .~n", [S, TP, TO]).

turtle_predicate("rdf:type", a) :- !.
turtle_predicate("rdfs:label", 'rdfs:label') :- !.
turtle_predicate(P, TP) :-
    atom_concat(':', P, TP).

turtle_object(O, O) :-
    (   sub_string(O, 0, 1, _, "\"")
    ;   O == "true"
    ;   O == "false"
    ),
    !.
turtle_object(O, TO) :-
    atom_concat(':', O, TO).

		 /*******************************
		 *            REPLAY            *
		 *******************************/

%   replay_figures(+Log, +EchoPort, +Params, -Replay): the recorded
%   robot session replayed on a fresh server started with the
%   experiment's robot id, its human partner declared first (as the
%   experiment's scenario ontology did): every request, each client
%   thread on its own connection (opened beforehand), in log order,
%   one at a time, no sleeps.  Total time and each request's round
%   trip; the events pushed meanwhile are read and counted.  Its floor,
%   measured right before: as many echo round trips (1 statement) as
%   requests were sent.

replay_figures(Log, EchoPort, Params, Replay) :-
    (   exists_file(Log)
    ->  progress("replay of ~w", [Log]),
        bench_log_requests(Log, Requests),
        echo_round_trip(EchoPort, Params, Echo),
        bench_with_server(['--robot-id=JIDOKUKA_ROBOT'], Port, _,
                          bench_with_connection(
                              Port, C,
                              ( call_ok(C, add, [["ACHILE_HUMAN1 rdf:type Human"]]),
                                wait_listed(C, ['ACHILE_HUMAN1'], 30),
                                replay(Port, Requests, Replay0)
                              ))),
        FloorSeconds is Replay0.requests * Echo.median / 1.0e6,
        Ratio is Replay0.seconds / FloorSeconds,
        MedianRatio is Replay0.stats.median / Echo.median,
        Replay = Replay0.put(_{echo:Echo, floor_s:FloorSeconds, ratio:Ratio,
                               median_ratio:MedianRatio}),
        print_replay(Replay)
    ;   format(user_error, "Notice: ~w not found: replay skipped.~n", [Log]),
        Replay = null
    ).

%   echo_round_trip(+EchoPort, +Params, -Stats): the echo server's round
%   trip for a one-statement request.

echo_round_trip(EchoPort, Params, Stats) :-
    bench_with_connection(
        EchoPort, E,
        bench_measure(Params.samples, Params.budget, _,
                      bench_call(E, check, [["ACHILE_HUMAN1 rdf:type Human"]], "true"),
                      true, Times)),
    bench_stats(Times, Stats).

replay(Port, Requests, replay{requests:N, connections:NConn, seconds:Seconds,
                              stats:Stats, ok:NOk, errors:Errors,
                              unanswered:NNone, unparsed:NBad, events:NEvents}) :-
    include([R]>>(R = request(_, _, _)), Requests, Good),
    length(Requests, NAll),
    length(Good, N),
    NBad is NAll - N,
    findall(T, member(request(T, _, _), Good), Threads0),
    sort(Threads0, Threads),
    length(Threads, NConn),
    with_connections(Threads, Port, Conns,
                     ( get_time(T0),
                       maplist(replay_request(Conns), Good, Outcomes),
                       get_time(T1)
                     )),
    Seconds is T1 - T0,
    findall(M, member(o(M, _, _), Outcomes), Times),
    bench_stats(Times, Stats),
    aggregate_all(count, member(o(_, ok, _), Outcomes), NOk),
    findall(Name, member(o(_, error(Name), _), Outcomes), Names0),
    msort(Names0, Names),
    clumped(Names, Errors0),
    findall(_{exception:E, count:K}, member(E-K, Errors0), Errors),
    aggregate_all(count, member(o(_, none, _), Outcomes), NNone),
    aggregate_all(sum(E), member(o(_, _, E), Outcomes), NEvents).

%   with_connections(+Threads, +Port, -Conns, :Goal): Goal with one
%   connection per thread name, Conns a list of Thread-Conn.

with_connections([], _, [], Goal) :-
    once(Goal).
with_connections([T|Ts], Port, [T-C|Cs], Goal) :-
    bench_with_connection(Port, C, with_connections(Ts, Port, Cs, Goal)).

replay_request(Conns, request(Thread, Method, Params), o(Micros, Kind, Events)) :-
    memberchk(Thread-C, Conns),
    get_time(T0),
    bench_request(C, Method, Params, reply(Message, Events), 30),
    get_time(T1),
    Micros is (T1 - T0) * 1.0e6,
    (   Message = ok(_)
    ->  Kind = ok
    ;   Message = error(Name, _)
    ->  Kind = error(Name)
    ;   Kind = none
    ).

print_replay(R) :-
    us_text(R.stats.median, Median),
    us_text(R.stats.p99, P99),
    us_text(R.stats.max, Max),
    us_text(R.echo.median, Echo),
    say("~nReplay of the 2011 robot session: ~d requests on ~d connections \c
         in ~3f s, ~1fx its floor (~d x the echo round trip of ~w = ~3f s); \c
         per request median ~w (~1fx echo), p99 ~w, max ~w; ~d ok, \c
         ~d unanswered, ~d unparsed, ~d events read~n",
        [R.requests, R.connections, R.seconds, R.ratio, R.requests, Echo,
         R.floor_s, Median, R.median_ratio, P99, Max, R.ok, R.unanswered,
         R.unparsed, R.events]),
    forall(member(E, R.errors),
           say("   error ~w: ~d~n", [E.exception, E.count])).

		 /*******************************
		 *            REPORT            *
		 *******************************/

%   print_size(+Figures0, -Figures): print a size's table; Figures is
%   Figures0 with the rows printed (`table`, see table_rows/2).

print_size(S, Figures) :-
    say("~n== ~D asserted triples (~D sent: ~D objects, ~D pieces of \c
         furniture, ~D rooms, ~d agents with ~D beliefs) ==~n",
        [S.triples, S.load.statements, S.world.objects, S.world.furniture,
         S.world.rooms, S.world.agents, S.load.belief_statements]),
    say("server memory: VmRSS ~w kB after the load, VmHWM ~w kB at the end~n~n",
        [S.memory_loaded.rss_kb, S.memory_end.hwm_kb]),
    table_rows(S, Rows),
    row(operation, median, p99, max, 'x floor', 'per second'),
    maplist(print_row, Rows),
    print_lookups(S.in_process),
    Figures = S.put(table, Rows).

%   print_lookups(+InProcess): rdf_db's part of each in-process
%   operation: the index lookups one call makes, and the call's median
%   shared among them, beside one bound rdf/3 probe (a lookup that
%   enumerates several triples costs more than a probe).

print_lookups(In) :-
    say("~nrdf_db's part of the in-process operations (index lookups a \c
         call, counted by rdf_statistics/1):~n~n", []),
    lookup_row(operation, 'lookups a call', 'median a lookup', 'x rdf/3'),
    forall(member(Op, In.operations),
           ( PerLookup is Op.stats.median / max(1, Op.lookups),
             format(string(Count), "~1f", [Op.lookups]),
             us_text(PerLookup, PerText),
             ratio_text(PerLookup / In.probe_us, Ratio),
             lookup_row(Op.label, Count, PerText, Ratio)
           )).

lookup_row(Label, Count, PerLookup, Ratio) :-
    say("~w~t~66|~w~t~17+~w~t~17+~w~n", [Label, Count, PerLookup, Ratio]).

%   table_rows(+Figures, -Rows): the rows of a size's table, each a dict
%   row{label, median_us, p99_us, max_us, floor, floor_us, ratio, per_s,
%   note}: times in microseconds, `floor` the name of the floor the
%   ratio is taken to (floor_us its time, if it is one), `null` where
%   there is nothing.

table_rows(S, Rows) :-
    Echo1 = S.echo.one.median,
    Echo100 = S.echo.batch.median,
    Assert = S.floors.rdf_assert_per_s,
    In = S.in_process,
    C = S.concurrent,
    E = S.events,
    findall(Row, ( member(Op, S.operations),
                   stats_row(Op.label, Op.stats, Op.floor, Op.floor_median,
                             Op.per_s, Row)
                 ), OpRows),
    findall(Row, ( member(Op, In.operations),
                   format(string(Label), "in process: ~w (x rdf/3)", [Op.label]),
                   stats_row(Label, Op.stats, rdf_probe, Op.floor_median,
                             Op.per_s, Row)
                 ), InRows),
    stats_row('echo round trip, 1 statement (floor)', S.echo.one,
              null, null, null, EchoRow1),
    stats_row('echo round trip, 100 statements (floor)', S.echo.batch,
              null, null, null, EchoRow100),
    probe_row(S.floors, ProbeRow),
    rate_row('bulk add, world load (x rdf_assert)', S.load.robot_per_s,
             Assert, LoadRow),
    rate_row('addForAgent, the beliefs (x rdf_assert)', S.load.belief_per_s,
             Assert, BeliefRow),
    stats_row('  a batch of 100 of the load (x echo)', S.load.batch,
              batch, Echo100, null, BatchRow),
    rate_row('bulk add, 2 requests in flight (x rdf_assert)',
             S.pipelined.per_s, Assert, PipelinedRow),
    rate_row('bulk add, 2 clients at once (x rdf_assert)',
             S.writers.per_s, Assert, WritersRow),
    rate_row('in process: bulk add, world load (x rdf_assert)',
             In.load.robot_per_s, Assert, InLoadRow),
    rate_row('in process: beliefs (x rdf_assert)', In.load.belief_per_s,
             Assert, InBeliefRow),
    stats_row('8 clients, mixed requests', C.server.stats,
              echo_8_clients, C.echo.stats.median, C.server.per_s, ClientsRow),
    stats_row('8 clients against echo (floor)', C.echo.stats,
              null, null, C.echo.per_s, EchoClientsRow),
    event_row('event, 1000 watchers on its predicate', E.same, Echo1, SameRow),
    event_row('event, 1000 watchers elsewhere', E.other, Echo1, OtherRow),
    append([ [EchoRow1, EchoRow100, ProbeRow, LoadRow, BeliefRow, BatchRow,
              PipelinedRow, WritersRow],
             OpRows,
             [InLoadRow, InBeliefRow],
             InRows,
             [ClientsRow, EchoClientsRow, SameRow, OtherRow]
           ], Rows).

stats_row(Label0, Stats, Floor, FloorMicros, PerSecond,
          row{label:Label, median_us:M, p99_us:P, max_us:X, floor:Floor,
              floor_us:FloorMicros, ratio:Ratio, per_s:PerSecond, note:null}) :-
    text_to_string(Label0, Label),
    json_number(Stats.median, M),
    json_number(Stats.p99, P),
    json_number(Stats.max, X),
    (   number(FloorMicros),
        number(M)
    ->  Ratio is M / FloorMicros
    ;   Ratio = null
    ).

probe_row(Floors, row{label:"bound rdf/3 probe, in process (floor)",
                      median_us:Floors.rdf_probe_us, p99_us:null, max_us:null,
                      floor:null, floor_us:null, ratio:null,
                      per_s:Floors.rdf_probe_per_s, note:null}).

%   rate_row: a rate against the floor's rate, as a ratio larger than 1
%   when it is slower.

rate_row(Label0, Rate, FloorRate,
         row{label:Label, median_us:null, p99_us:null, max_us:null,
             floor:rdf_assert, floor_us:null, ratio:Ratio, per_s:Rate,
             note:null}) :-
    text_to_string(Label0, Label),
    Ratio is FloorRate / Rate.

event_row(Label0, Result, EchoMedian, Row) :-
    stats_row(Label0, Result.latency, one, EchoMedian, null, Row0),
    format(string(Missed), "~d missed", [Result.missed]),
    Row = Row0.put(note, Missed).

json_number(X, Y) :-
    (   number(X)
    ->  Y = X
    ;   Y = null
    ).

%   print_row(+Row): a row of table_rows/2 as a line of the table.

print_row(R) :-
    us_text(R.median_us, M),
    us_text(R.p99_us, P),
    us_text(R.max_us, X),
    (   number(R.ratio)
    ->  ratio_text(R.ratio, Ratio)
    ;   Ratio = "-"
    ),
    (   string(R.note)
    ->  PS = R.note
    ;   count_text(R.per_s, PS)
    ),
    row(R.label, M, P, X, Ratio, PS).

%   row(+Label, +Median, +P99, +Max, +Ratio, +PerSecond): one line of the
%   table, the cells already texts.

row(Label, Median, P99, Max, Ratio, PerSecond) :-
    say("~w~t~66|~w~t~11+~w~t~11+~w~t~11+~w~t~9+~w~n",
        [Label, Median, P99, Max, Ratio, PerSecond]).

us_text(X, Text) :-
    bench_micros(X, Text, [units(auto)]).

ms_text(X, Text) :-
    format(string(Text), "~1f ms", [X / 1000]).

ratio_text(Expr, Text) :-
    X is Expr,
    format(string(Text), "~1fx", [X]).

count_text(X, Text) :-
    (   number(X)
    ->  format(string(Text), "~0f", [X])
    ;   Text = "-"
    ).

		 /*******************************
		 *           SCALING            *
		 *******************************/

%   scaling(+PerSize, -Scaling): the figures of the largest size
%   against those at 100,000 triples (null unless both were measured):
%   each operation's median, the bulk rate, the event latency and the
%   8 clients' throughput, as a ratio larger than 1 when the larger
%   world is slower.

scaling(PerSize, Scaling) :-
    (   member(Base, PerSize),
        Base.triples =:= 100000,
        last(PerSize, Large),
        Large.triples > 100000
    ->  findall(R, scaling_row(Base, Large, R), Rows),
        Scaling = scaling{from:100000, to:Large.triples, rows:Rows},
        say("~nScaling: ~D against 100,000 triples (slower by)~n",
            [Large.triples]),
        forall(member(R, Rows),
               ( ratio_text(R.ratio, T),
                 say("   ~w~t~58|~w~n", [R.label, T])
               ))
    ;   Scaling = null
    ).

scaling_row(Base, Large, row{key:Key, label:Label, ratio:Ratio}) :-
    member(Op, Large.operations),
    member(BaseOp, Base.operations),
    BaseOp.key == Op.key,
    Key = Op.key,
    Label = Op.label,
    Ratio is Op.stats.median / BaseOp.stats.median.
scaling_row(Base, Large, row{key:bulk_add, label:"bulk add (rate)", ratio:Ratio}) :-
    Ratio is Base.load.robot_per_s / Large.load.robot_per_s.
scaling_row(Base, Large, row{key:event_same, label:"event, 1000 watchers on its predicate",
                             ratio:Ratio}) :-
    number(Base.events.same.latency.median),
    number(Large.events.same.latency.median),
    Ratio is Large.events.same.latency.median / Base.events.same.latency.median.
scaling_row(Base, Large, row{key:concurrent, label:"8 clients (throughput)", ratio:Ratio}) :-
    Ratio is Base.concurrent.server.per_s / Large.concurrent.server.per_s.

		 /*******************************
		 *           TARGETS            *
		 *******************************/

%   targets(+PerSize, +Startup, +Turtle, +Replay, +Scaling, -Targets):
%   the targets of the issue, each with the figure measured and whether
%   it is met (pass: true, false, or null when not measured in this
%   run; verdict: `PASS`, `MISS` or `not measured`, and the same for the
%   aim where there is one).  Socket figures at 100,000 triples (else
%   the largest size measured).

targets(PerSize, Startup, Turtle, Replay, Scaling, Targets) :-
    (   member(Ref, PerSize),
        Ref.triples =:= 100000
    ->  true
    ;   last(PerSize, Ref)
    ),
    findall(T, target(Ref, PerSize, Startup, Turtle, Replay, Scaling, T), Targets0),
    maplist(with_verdict, Targets0, Targets),
    say("~nTargets (socket figures at ~D triples; medians unless said)~n",
        [Ref.triples]),
    forall(member(T, Targets),
           (   get_dict(aim_verdict, T, AimV)
           ->  say("   ~w~t~76|~w~t~30+~w (aim: ~w)~n",
                   [T.target, T.figure, T.verdict, AimV])
           ;   say("   ~w~t~76|~w~t~30+~w~n", [T.target, T.figure, T.verdict])
           )).

with_verdict(T0, T) :-
    verdict(T0.pass, V),
    (   get_dict(aim, T0, Aim)
    ->  verdict(Aim, AimV),
        T = T0.put(_{verdict:V, aim_verdict:AimV})
    ;   T = T0.put(verdict, V)
    ).

verdict(true, "PASS").
verdict(false, "MISS").
verdict(null, "not measured").

target(Ref, _, _, _, _, _, target{target:Target, figure:Figure, pass:Pass, aim:Aim}) :-
    member(Key, [check_asserted, check_type, check_property, find_1, find_2,
                 find_3, add_1, lookup_label, lookup_name]),
    member(Op, Ref.operations),
    Op.key == Key,
    format(string(Target), "~w: within 3x echo (aim < 100 us)", [Op.label]),
    us_text(Op.stats.median, M),
    format(string(Figure), "~w = ~1fx echo", [M, Op.ratio]),
    bool(Op.ratio =< 3, Pass),
    bool(Op.stats.median < 100, Aim).
target(Ref, _, _, _, _, _, target{target:"bulk add: >= 100,000 statements/s (batches of 100)",
                                  figure:Figure, pass:Pass}) :-
    bulk_target(Ref.load.robot_per_s, Figure, Pass).
target(Ref, _, _, _, _, _, target{target:"bulk add, 2 requests in flight: >= 100,000 statements/s",
                                  figure:Figure, pass:Pass}) :-
    bulk_target(Ref.pipelined.per_s, Figure, Pass).
target(Ref, _, _, _, _, _, target{target:"bulk add, 2 clients at once: >= 100,000 statements/s",
                                  figure:Figure, pass:Pass}) :-
    bulk_target(Ref.writers.per_s, Figure, Pass).
target(Ref, _, _, _, _, _, target{target:"event latency, 1000 watchers: median < 1 ms",
                                  figure:Figure, pass:Pass}) :-
    L = Ref.events.same.latency,
    us_text(L.median, Figure),
    bool(L.median < 1000, Pass).
target(Ref, _, _, _, _, _, target{target:"event latency, 1000 watchers: p99 < 5 ms",
                                  figure:Figure, pass:Pass}) :-
    L = Ref.events.same.latency,
    us_text(L.p99, Figure),
    bool(L.p99 < 5000, Pass).
target(Ref, _, _, _, _, _, target{target:"event latency, 1000 watchers: 0 missed",
                                  figure:Figure, pass:Pass}) :-
    Missed is Ref.events.same.missed + Ref.events.other.missed,
    format(string(Figure), "~d missed", [Missed]),
    bool(Missed =:= 0, Pass).
target(_, _, Startup, _, _, _, target{target:"startup to listening, bundled ontology: < 0.5 s",
                                      figure:Figure, pass:Pass}) :-
    ms_text(Startup.stats.median, Figure),
    bool(Startup.stats.median < 500000, Pass).
target(_, _, _, Turtle, _, _, target{target:"loading 1M triples of Turtle: < 10 s",
                                     figure:Figure, pass:Pass}) :-
    (   Turtle.triples >= 1000000
    ->  format(string(Figure), "~2f s to listening", [Turtle.startup_s]),
        bool(Turtle.startup_s < 10, Pass)
    ;   format(string(Figure), "(only ~D triples loaded)", [Turtle.triples]),
        Pass = null
    ).
target(_, PerSize, _, _, _, _, target{target:"RSS at 1M asserted triples: < 1 GiB",
                                      figure:Figure, pass:Pass}) :-
    (   member(S, PerSize),
        S.triples >= 1000000
    ->  RSS = S.memory_loaded.rss_kb,
        format(string(Figure), "~1f MiB", [RSS / 1024]),
        bool(RSS < 1048576, Pass)
    ;   Figure = "(no 1M size)",
        Pass = null
    ).
target(_, _, _, _, Replay, _, target{target:"robot session replay: < 1 s in total",
                                     figure:Figure, pass:Pass}) :-
    (   Replay == null
    ->  Figure = "(no log)",
        Pass = null
    ;   format(string(Figure), "~3f s = ~1fx floor", [Replay.seconds, Replay.ratio]),
        bool(Replay.seconds < 1, Pass)
    ).
target(_, _, _, _, _, Scaling, target{target:Target, figure:Figure, pass:Pass}) :-
    Scaling \== null,
    member(Row, Scaling.rows),
    format(string(Target), "~D vs 100k, ~w: <= 2x", [Scaling.to, Row.label]),
    ratio_text(Row.ratio, Figure),
    bool(Row.ratio =< 2, Pass).

%   bulk_target(+Rate, -Figure, -Pass): a bulk rate against its target.

bulk_target(Rate, Figure, Pass) :-
    RateInt is integer(Rate),
    format(string(Figure), "~D stmt/s", [RateInt]),
    bool(Rate >= 100000, Pass).

bool(Goal, Bool) :-
    (   call(Goal)
    ->  Bool = true
    ;   Bool = false
    ).

		 /*******************************
		 *             JSON             *
		 *******************************/

write_json(File, Results) :-
    setup_call_cleanup(
        open(File, write, Out, [encoding(utf8)]),
        ( json_write_dict(Out, Results, [width(100)]),
          nl(Out)
        ),
        close(Out)).
