/*  Where the time of an add of 100 statements goes.

        swipl bench/bench_batch.pl [--facts=100000] [--rounds=10]
                                   [--per-round=16]

    In one process: the world of bench_world/2 (`facts` triples) is
    added with oro_add/2; then batches of 100 new statements (25 new
    objects a batch, as the world's: typed, on a piece of furniture,
    coloured, visible) are added
    in `rounds` rounds.  Each round adds `per-round` batches through
    each of two paths, one after the other, so that a slow spell of the
    machine falls on both:

      - in a tight loop: oro_add/2 of each batch, back to back;
      - over a loopback socket, one request at a time: the bench sends
        each batch as an `add` request (the text liboro sends) and
        waits for its reply before it sends the next; a thread of this
        process serves the connection with the server's own connection
        loop (server/oro_server.pl), as a connection worker of the
        server does.

    For each path, the CPU time and the inferences of the thread that
    does the work, per batch.  Then the steps of the server path that
    come before the store, on the texts of `per-round` other batches
    (nothing is added): reading the request from a stream
    (oro_protocol), decoding its parameter into the statements' texts
    (oro_methods), and parsing them (oro_parse).  Each figure is the
    median over the rounds of its per-batch mean.

    The inferences show whether a path does more work; the CPU time
    what it costs.  A builtin that scans a text counts one inference
    however long the text.  Prints a table.
*/

:- prolog_load_context(directory, Dir),
   atom_concat(Dir, '/../prolog', Lib),
   asserta(user:file_search_path(library, Lib)),
   asserta(user:file_search_path(oro_bench, Dir)).

:- use_module(library(oro)).
:- use_module(library(oro/oro_parse), [oro_statements/3]).
:- use_module(oro_bench('../server/oro_server')).
:- use_module(oro_bench('../server/oro_protocol'),
              [oro_reader/3, oro_read_request/3]).
:- use_module(oro_bench('../server/oro_methods'), []).
:- use_module(library(socket)).
:- use_module(library(memfile)).
:- use_module(library(main), [argv_options/3]).
:- use_module(library(option)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(error)).
:- use_module(library(yall)).
:- use_module(bench_common).

:- initialization(main, main).

opt_type(facts, facts, nonneg).
opt_type(rounds, rounds, nonneg).
opt_type(per_round, per_round, nonneg).

main :-
    current_prolog_flag(argv, Argv),
    argv_options(Argv, _, Options),
    option(facts(Facts), Options, 100000),
    option(rounds(Rounds), Options, 10),
    option(per_round(PerRound), Options, 16),
    must_be(positive_integer, Rounds),
    must_be(positive_integer, PerRound),
    bench_machine,
    oro_init([]),
    bench_world(Facts, World),
    bench_batches(World, 100, WorldBatches),
    maplist(oro_add(myself), WorldBatches),
    format("~nWorld: ~D statements added in process.  ~d rounds of ~d \c
            batches of 100 through each path.~n~n", [Facts, Rounds, PerRound]),
    Writes is 2 * Rounds * PerRound,
    First is Facts // 4 + 1,                % after the world's objects
    new_batches(First, Writes, Batches),
    length(Steps, PerRound),
    append(Steps0, _, Batches),
    length(Steps0, PerRound),
    maplist(step_batch, Steps0, Steps),     % same shape, never added
    maplist(request_text, Steps, Texts),
    with_socket_server(Conn, Server,
                       rounds(Rounds, PerRound, Batches, Texts, Conn, Server,
                              Samples)),
    report(Samples).

%   new_batches(+From, +Count, -Batches): Count batches of 100
%   statements of new objects (bench_object_statement/2), from `objFrom`
%   on.

new_batches(From, Count, Batches) :-
    To is From + 25 * Count - 1,
    findall(S, ( between(From, To, I), bench_object_statement(I, S) ),
            Statements),
    bench_batches(Statements, 100, Batches).

%   step_batch(+Batch, -Step): Batch with its subjects renamed, so that
%   the steps never parse the texts of a batch that is added.

step_batch(Batch, Step) :-
    maplist([S0, S]>>( string_concat("obj", Rest, S0),
                       string_concat("sobj", Rest, S)
                     ), Batch, Step).

%   request_text(+Batch, -Text): the bytes of the `add` request of
%   Batch, as bench_send/3 sends them.

request_text(Batch, Text) :-
    with_output_to(string(Text),
                   ( current_output(Out),
                     bench_send(bench_conn(none, Out), add, [Batch])
                   )).

		 /*******************************
		 *      THE SOCKET'S SERVER     *
		 *******************************/

%   with_socket_server(-Conn, -Server, :Goal): run Goal with Conn
%   connected to a thread Server of this process that serves the
%   connection with the server's connection loop.

:- meta_predicate with_socket_server(-, -, 0).

with_socket_server(Conn, Server, Goal) :-
    tcp_socket(Socket),
    tcp_setopt(Socket, reuseaddr),
    tcp_bind(Socket, '127.0.0.1':Port),
    tcp_listen(Socket, 1),
    thread_create(serve_one(Socket), Server, []),
    call_cleanup(bench_with_connection(Port, Conn, Goal),
                 ( thread_join(Server, _),
                   tcp_close_socket(Socket)
                 )).

serve_one(Socket) :-
    tcp_accept(Socket, Client, Peer),
    get_time(Now),
    setup_call_cleanup(
        tcp_open_socket(Client, Pair),
        ( tcp_setopt(Client, nodelay),
          oro_server:serve_stream(_{started:Now}, 1, Pair, Peer)
        ),
        close(Pair, [force(true)])).

		 /*******************************
		 *            ROUNDS            *
		 *******************************/

rounds(Rounds, PerRound, Batches, Texts, Conn, Server, Samples) :-
    numlist(1, Rounds, Rs),
    foldl(round(PerRound, Texts, Conn, Server), Rs, Samples, Batches, _).

round(PerRound, Texts, Conn, Server, _,
      round{tight:Tight, socket:Socket, read:Read, decode:Decode,
            parse:Parse},
      Batches0, Batches) :-
    length(TightBatches, PerRound),
    length(SocketBatches, PerRound),
    append(TightBatches, Batches1, Batches0),
    append(SocketBatches, Batches, Batches1),
    per_batch(PerRound, maplist(oro_add(myself), TightBatches), Tight),
    thread_cost(Server, C0, I0),
    forall(member(B, SocketBatches), bench_call(Conn, add, [B])),
    thread_cost(Server, C1, I1),
    cost_per(PerRound, C0-I0, C1-I1, Socket),
    maplist(read_request, Texts, Requests),
    per_batch(PerRound, maplist(read_request, Texts, _), Read),
    per_batch(PerRound, maplist(decode_request, Requests, _), Decode),
    maplist(decode_request, Requests, Statements),
    per_batch(PerRound, maplist(parse_statements, Statements), Parse).

%   per_batch(+N, :Goal, -Cost): what Goal costs this thread, divided
%   by N: cost{cpu:Micros, inferences:Inferences}.

:- meta_predicate per_batch(+, 0, -).

per_batch(N, Goal, Cost) :-
    garbage_collect,
    thread_self(Me),
    thread_cost(Me, C0, I0),
    once(Goal),
    thread_cost(Me, C1, I1),
    cost_per(N, C0-I0, C1-I1, Cost).

thread_cost(Thread, CPU, Inferences) :-
    thread_statistics(Thread, cputime, CPU),
    thread_statistics(Thread, inferences, Inferences).

cost_per(N, C0-I0, C1-I1, cost{cpu:Micros, inferences:Inferences}) :-
    Micros is (C1 - C0) * 1.0e6 / N,
    Inferences is (I1 - I0) / N.

read_request(Text, Request) :-
    setup_call_cleanup(
        ( new_memory_file(File),
          insert_memory_file(File, 0, Text),
          open_memory_file(File, read, In, [encoding(octet)])
        ),
        ( oro_reader(In, Reader, []),
          oro_read_request(Reader, Request, _)
        ),
        ( close(In),
          free_memory_file(File)
        )).

%   decode_request(+Request, -Statements): the texts of the statements
%   of an `add` request, as the server's dispatcher decodes them.

decode_request(request(Method, Params), Statements) :-
    oro_methods:decoded(Method, Params, _, _, _, [Statements]).

parse_statements(Statements) :-
    oro_statements(Statements, Triples, []),
    must_be(ground, Triples).

		 /*******************************
		 *            REPORT            *
		 *******************************/

report(Samples) :-
    format("| path or step | CPU a batch | inferences a batch |~n\c
            |---|---|---|~n"),
    forall(row(Key, Label), report_row(Samples, Key, Label)),
    maplist(cpu_ratio, Samples, Ratios),
    bench_summary(Ratios, Ratio, _),
    format("~nOver the socket / tight loop, CPU (median of the rounds' \c
            ratios): ~2fx~n", [Ratio]).

cpu_ratio(Sample, Ratio) :-
    Ratio is Sample.socket.cpu / Sample.tight.cpu.

row(tight, "oro_add/2, tight loop").
row(socket, "add requests over the socket, one at a time (serving thread)").
row(read, "step: read the request").
row(decode, "step: decode the set of statements").
row(parse, "step: parse the statements").

report_row(Samples, Key, Label) :-
    maplist(sample_cost(Key), Samples, CPUs, Infs),
    bench_summary(CPUs, CPU, _),
    bench_summary(Infs, Inf, _),
    bench_micros(CPU, Text),
    format("| ~w | ~w | ~0f |~n", [Label, Text, Inf]).

sample_cost(Key, Sample, CPU, Inferences) :-
    get_dict(Key, Sample, cost{cpu:CPU, inferences:Inferences}).
