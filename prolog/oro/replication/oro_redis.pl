:- module(oro_redis,
          [ oro_redis_start/1,          % +Options
            oro_redis_options/1,        % +ServerOptions
            oro_redis_stop/0,
            oro_redis_status/1,         % -Status
            oro_redis_sync/1            % +Seconds
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(redis)).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(pairs)).
:- use_module(library(option)).
:- use_module(library(debug)).
:- use_module(library(settings)).
:- use_module(library(oro/oro_store)).
:- use_module(library(oro/oro_persist)).
:- use_module(library(oro/reason/oro_reason), [oro_functional_property/2]).
:- use_module(library(oro/oro_agents), [oro_create_agent/2]).

/** <module> Several robots: sharing models through Redis streams

Each oro *node* (`--node=NAME`) publishes the committed changes of the
models it shares to its own Redis stream, `oro:node:NAME`, and follows
the streams of other nodes, applying each entry to the model named
after the node that wrote it (an agent model: what that robot
believes).  With `share_world(true)` the model `world` is written by
every node through one stream, `oro:world`, which every node applies
in stream order.

Publishing:

  - An rdf_monitor/2 callback notes, in the writing thread, every
    triple a transaction adds to or removes from a graph of a shared
    model, as `a(Model, Layer, S, P, O)` or `r(...)` (Layer is the
    memory profile, or `mask` for an ontology triple the model removed).
    When the transaction commits it queues one entry per model on the
    publisher's queue and returns: a local write never waits for Redis.
  - The publisher thread takes the entries in commit order and appends
    them (XADD, trimmed to about `stream_length` entries) in pipelined
    batches.  When Redis is unreachable it retries with a growing pause
    (up to 2 s); entries wait in its queue.  Past `buffer` waiting
    entries new changes are no longer queued: a warning says so once,
    and once Redis is back the node publishes a *snapshot* of each
    shared model (all its triples, layer by layer) instead of the lost
    entries.
  - A snapshot is also published when the publisher starts and every
    `snapshot_every` entries, and its id is kept under the key
    `oro:snapshot:STREAM`, so that the stream (trimmed) always holds
    the last snapshot and what followed it.
  - A transaction that applies an entry from Redis (its id is
    oro(redis_apply(Stream))) is never published: no loops, no echoes.

Following:

  - The follower thread reads (XREAD, blocking at most 1 s) every
    followed stream from the last entry it applied, and applies the
    entries of each read (up to `batch`), in stream order, as one store
    transaction together with the record of the last one's id
    (oro_persist_record/1): with a database directory the restart goes
    on from there, exactly once.  A node that has
    applied nothing of a stream, or whose last entry was trimmed away,
    starts from its last snapshot.
  - A snapshot entry makes each graph of the local model equal to the
    snapshot's (only the difference is written); a change entry adds
    and removes its triples.  The watchers see these transactions like
    any other change: the entries of one read as one change (a node
    keeping up reads one entry at a time; one catching up, many).
  - World convergence: every node, the writer included, applies every
    entry of `oro:world` in stream order, and an added value of an
    owl:FunctionalProperty replaces the subject's other values.  So the
    last writer in Redis' order wins: once every node has applied the
    stream, they all hold the same world.
*/

:- setting(buffer, positive_integer, 100000,
           'Entries waiting to be published past which changes are dropped \c
           (a snapshot is published once Redis is back)').
:- setting(stream_length, positive_integer, 200000,
           'Entries Redis keeps in a node\'s stream (MAXLEN ~)').
:- setting(snapshot_every, positive_integer, 50000,
           'Entries published between two snapshots of the shared models').
:- setting(batch, positive_integer, 500,
           'Entries appended or read in one round trip').

:- dynamic
    config/2,                       % Key, Value
    applied/2,                      % Stream, Id
    published/1.                    % Count since the last snapshot

%   config/2, applied/2 and published/1 are owned by this module:
%   config/2 is written by start/stop under the `oro_redis` mutex,
%   applied/2 by the follower thread, published/1 by the publisher.

		 /*******************************
		 *          START/STOP          *
		 *******************************/

%!  oro_redis_start(+Options) is det.
%
%   Connect this node to Redis.  Options:
%
%     - redis(+URL)
%       `redis://HOST:PORT` (required).
%     - node(+Name)
%       The name of this node (required): its stream is
%       `oro:node:Name`, and other nodes' model of it is named Name.
%     - share(+Models)
%       The models whose changes are published (default [myself]).
%     - follow(+Nodes)
%       The nodes whose streams are applied: a list of names, or `*`
%       for every node that has published (default []).
%     - share_world(+Bool)
%       Replicate the model `world`, written by every node (default
%       false).
%
%   @error domain_error(redis_url, URL) if URL is not redis://HOST:PORT.
%   @error existence_error(option, Name) if redis(URL) or node(Name) is
%   missing.
%   @error existence_error(agent, Model) if a shared model does not
%   exist.

:- predicate_options(oro_redis_start/1, 1,
                     [ redis(atom), node(atom), share(list(atom)),
                       follow(any), share_world(boolean)
                     ]).

oro_redis_start(Options) :-
    must_be(list, Options),
    required_option(redis(URL), Options),
    required_option(node(Node), Options),
    must_be(atom, Node),
    redis_address(URL, Address),
    option(share(Share0), Options, [myself]),
    must_be(list(atom), Share0),
    maplist(oro_resolve_model, Share0, Share1),
    option(follow(Follow), Options, []),
    must_be(oro_redis_follow, Follow),
    option(share_world(World), Options, false),
    must_be(boolean, World),
    (   World == true
    ->  oro_create_model(world),
        Share = [world|Share1]
    ;   Share = Share1
    ),
    oro_redis_stop,
    restore_applied,
    flag(oro_redis_running, _, 1),
    flag(oro_redis_outage, _, 0),
    with_mutex(oro_redis,
               forall(member(K-V, [ address-Address, node-Node,
                                    share-Share, follow-Follow,
                                    world-World
                                  ]),
                      assertz(config(K, V)))),
    message_queue_create(_, [alias(oro_redis_out)]),
    monitor_mask(Mask),
    rdf_monitor(oro_redis:monitor, Mask),
    flag(oro_redis_dropped, _, 0),
    flag(oro_redis_snapshot_due, _, 1),
    retractall(published(_)),
    assertz(published(0)),
    thread_create(publisher, _, [alias(oro_redis_publisher)]),
    thread_create(follower, _, [alias(oro_redis_follower)]),
    debug(oro(redis), 'Node ~w on ~w: sharing ~w, following ~w',
          [Node, Address, Share, Follow]).

:- multifile error:has_type/2.

error:has_type(oro_redis_follow, X) :-
    (   X == (*)
    ->  true
    ;   is_list(X),
        maplist(atom, X)
    ).

required_option(Option, Options) :-
    (   option(Option, Options)
    ->  true
    ;   functor(Option, Name, _),
        existence_error(option, Name)
    ).

%   redis_address(+URL, -Host:Port)

redis_address(URL, Host:Port) :-
    must_be(atomic, URL),
    (   atom_concat('redis://', Rest, URL),
        split_string(Rest, ":", "/", [HostS, PortS]),
        HostS \== "",
        number_string(Port, PortS),
        integer(Port),
        between(1, 65535, Port)
    ->  atom_string(Host, HostS)
    ;   domain_error(redis_url, URL)
    ).

%!  oro_redis_options(+ServerOptions) is det.
%
%   Start this node as the command line says: redis(URL), node(Name),
%   share(Text), follow(Text) (names separated by commas, or `*`) and
%   share_world(Bool), as argv_options/3 gives them.  Nothing happens
%   without redis(URL).
%
%   @error existence_error(option, node) if redis(URL) comes without
%   node(Name).

oro_redis_options(Options) :-
    (   option(redis(URL), Options)
    ->  required_option(node(Node), Options),
        option(share(ShareText), Options, myself),
        names(ShareText, Share),
        option(follow(FollowText), Options, ''),
        (   FollowText == (*)
        ->  Follow = (*)
        ;   names(FollowText, Follow)
        ),
        option(share_world(World), Options, false),
        oro_redis_start([ redis(URL), node(Node), share(Share),
                          follow(Follow), share_world(World)
                        ])
    ;   true
    ).

names(Text, Names) :-
    split_string(Text, ",", " ", Parts0),
    exclude(==(""), Parts0, Parts),
    maplist(atom_string, Names, Parts).

%!  oro_redis_stop is det.
%
%   Disconnect this node from Redis: stop the publisher (entries not
%   yet published are dropped) and the follower.  Nothing happens if
%   the node is not connected.

oro_redis_stop :-
    (   config(node, _)
    ->  rdf_monitor(oro_redis:monitor, [-all]),
        flag(oro_redis_running, _, 0),
        thread_send_message(oro_redis_out, stop),
        thread_join(oro_redis_publisher, _),
        thread_join(oro_redis_follower, _),
        catch(message_queue_destroy(oro_redis_out), _, true),
        with_mutex(oro_redis, retractall(config(_, _)))
    ;   true
    ).

%   running: the node has not been told to stop.  The publisher and
%   follower threads look at it before each round trip and each pause
%   (XREAD blocks 1 s at most), so oro_redis_stop/0 waits about a second
%   at most; it sends the publisher a `stop` message too.

running :-
    flag(oro_redis_running, 1, 1).

%!  oro_redis_status(-Status) is det.
%
%   Status is a dict: `node`, `queued` (entries waiting to be
%   published), `published` (entries appended since the last
%   snapshot), `applied` (a list of Stream-Id, the last entry applied
%   from each stream), `dropped` (changes not queued since the buffer
%   was last full).

oro_redis_status(Status) :-
    (   config(node, Node)
    ->  true
    ;   Node = none
    ),
    (   catch(message_queue_property(oro_redis_out, size(Queued)), _, fail)
    ->  true
    ;   Queued = 0
    ),
    (   published(Published)
    ->  true
    ;   Published = 0
    ),
    findall(S-Id, applied(S, Id), Applied),
    flag(oro_redis_dropped, Dropped, Dropped),
    Status = redis{node:Node, queued:Queued, published:Published,
                   applied:Applied, dropped:Dropped}.

%!  oro_redis_sync(+Seconds) is semidet.
%
%   Wait at most Seconds until every change committed so far is
%   published; fails if it is not by then.

oro_redis_sync(Seconds) :-
    must_be(number, Seconds),
    thread_self(Me),
    thread_send_message(oro_redis_out, sync(Me)),
    thread_get_message(Me, oro_redis_synced, [timeout(Seconds)]).

		 /*******************************
		 *           MONITOR            *
		 *******************************/

monitor_mask([-all, +assert, +retract, +transaction]).

%   A store rebuild (oro_store_rebuild/0) empties rdf_db and fills it
%   again with the same triples: the monitor is off meanwhile, or the
%   whole store would be published again.

:- multifile oro_store:rebuild_hook/1.

oro_store:rebuild_hook(suspend) :-
    config(node, _),
    rdf_monitor(oro_redis:monitor, [-all]).
oro_store:rebuild_hook(resume) :-
    config(node, _),
    monitor_mask(Mask),
    rdf_monitor(oro_redis:monitor, Mask).

%   monitor(+Event): the rdf_monitor/2 callback.  Tiny and total: it
%   notes the changed triples of shared models in the writing thread's
%   queue (oro_redis_ops) and, at the commit, queues them.

monitor(Event) :-
    catch(monitor_(Event), E, print_message(warning, E)),
    !.
monitor(_).

monitor_(transaction(begin(0), Id)) :-
    !,
    (   applying(Id)
    ->  nb_setval(oro_redis_skip, true)
    ;   nb_setval(oro_redis_skip, false)
    ).
monitor_(transaction(end(0), _)) :-
    !,
    (   nb_current(oro_redis_ops, Queue)
    ->  oro_drain_queue(Queue, Ops),
        (   Ops == []
        ->  true
        ;   queue_entries(Ops)
        )
    ;   true
    ).
monitor_(transaction(_, _)) :-
    !.
monitor_(assert(S, P, O, G)) :-
    note(a, S, P, O, G).
monitor_(retract(S, P, O, G)) :-
    note(r, S, P, O, G).

applying(oro(redis_apply(_))).
applying(log(oro(_, redis_apply(_)))).

note(Sign, S, P, O, G) :-
    \+ nb_current(oro_redis_skip, true),
    oro_graph_layer(G, Model, Layer0),
    config(share, Share),
    memberchk(Model, Share),
    !,
    layer_key(Layer0, Layer),
    ops_queue(Queue),
    op(Sign, Layer, S, P, O, Op),
    thread_send_message(Queue, Model-Op).
note(_, _, _, _, _).

op(a, Layer, S, P, O, a(Layer, S, P, O)).
op(r, Layer, S, P, O, r(Layer, S, P, O)).

layer_key(profile(P), P) :- !.
layer_key(mask, mask).

ops_queue(Queue) :-
    (   nb_current(oro_redis_ops, Queue0)
    ->  Queue = Queue0
    ;   message_queue_create(Queue),
        nb_setval(oro_redis_ops, Queue)
    ).

%   queue_entries(+Ops): one entry per model, unless the buffer is
%   full (then the change is counted as dropped and a snapshot will
%   replace it).

queue_entries(Ops) :-
    setting(buffer, Max),
    (   message_queue_property(oro_redis_out, size(Size)),
        Size < Max,
        flag(oro_redis_dropped, 0, 0)
    ->  model_entries(Ops, Entries),
        forall(member(E, Entries),
               thread_send_message(oro_redis_out, E))
    ;   flag(oro_redis_dropped, N, N+1),
        (   N =:= 0
        ->  print_message(warning, oro_redis(buffer_full(Max)))
        ;   true
        )
    ).

%   model_entries(+Pairs, -Entries): the Model-Op pairs of a
%   transaction as one change(Model, Ops) a model, the Ops in the order
%   noted.  A transaction usually changes one model.

model_entries([Model-Op|Pairs], Entries) :-
    (   same_model(Pairs, Model)
    ->  pairs_values(Pairs, Ops),
        Entries = [change(Model, [Op|Ops])]
    ;   keysort([Model-Op|Pairs], Sorted),   % stable: order kept
        group_pairs_by_key(Sorted, Groups),
        findall(change(M, Ops), member(M-Ops, Groups), Entries)
    ).

same_model([], _).
same_model([M-_|Pairs], Model) :-
    M == Model,
    same_model(Pairs, Model).

		 /*******************************
		 *          PUBLISHER           *
		 *******************************/

publisher :-
    publisher_loop(none, [], 0.05).

%   publisher_loop(+Conn, +Pending, +Pause): Pending are entries taken
%   from the queue but not yet appended (Redis was unreachable).

publisher_loop(Conn, _, _) :-
    \+ running,
    !,
    close_connection(Conn).
publisher_loop(Conn0, Pending0, Pause) :-
    setting(batch, Batch),
    (   Pending0 \== []
    ->  Pending = Pending0
    ;   flag(oro_redis_snapshot_due, 1, 1)  % at start: publish at once
    ->  take_more(Batch, Pending)
    ;   thread_get_message(oro_redis_out, First),
        First \== stop
    ->  Max is Batch - 1,
        take_more(Max, More),
        Pending = [First|More]
    ;   Pending = stop
    ),
    (   Pending == stop
    ->  publisher_loop(Conn0, [], Pause)    % running is false now
    ;   catch(publish(Conn0, Conn, Pending), E, redis_failed(E, Conn0))
    ->  publisher_loop(Conn, [], 0.05)
    ;   sleep(Pause),
        Pause1 is min(2, Pause*2),
        publisher_loop(none, Pending, Pause1)
    ).

take_more(0, []) :- !.
take_more(N, [E|Es]) :-
    thread_get_message(oro_redis_out, E, [timeout(0)]),
    E \== stop,
    !,
    N1 is N - 1,
    take_more(N1, Es).
take_more(_, []).

%   redis_failed(+Error, +Conn): Redis could not be reached (or
%   answered an error): say so, close the connection and fail, so that
%   the caller retries.

redis_failed(E, Conn) :-
    (   flag(oro_redis_outage, 0, 1)        % said once an outage
    ->  print_message(warning, oro_redis(unreachable(E)))
    ;   debug(oro(redis), 'Redis still unreachable: ~p', [E])
    ),
    close_connection(Conn),
    fail.

close_connection(none) :- !.
close_connection(Conn) :-
    catch(redis_disconnect(Conn, [force(true)]), _, true).

connection(none, Conn) :-
    !,
    config(address, Address),
    redis_connect(Address, Conn, [reconnect(false)]),
    (   flag(oro_redis_outage, 1, 0)
    ->  print_message(informational, oro_redis(reconnected(Address)))
    ;   true
    ),
    debug(oro(redis), 'Connected to ~w', [Address]).
connection(Conn, Conn).

%   publish(+Conn0, -Conn, +Entries): append Entries.  A snapshot of
%   the shared models replaces them (and the entries still queued) when
%   the publisher starts, every snapshot_every entries, and after an
%   overflow (then including the world model).

publish(Conn0, Conn, Entries0) :-
    connection(Conn0, Conn),
    (   flag(oro_redis_dropped, D, D),
        D > 0
    ->  snapshot_entries(true, Entries0, Entries)
    ;   flag(oro_redis_snapshot_due, 1, 1)
    ->  snapshot_entries(false, Entries0, Entries)
    ;   Entries = Entries0
    ),
    exclude(sync_request, Entries, Changes),
    maplist(xadd_command, Changes, Commands),
    (   Commands == []
    ->  true
    ;   redis(Conn, Commands)
    ),
    snapshot_ids(Conn, Changes, Commands),
    flag(oro_redis_snapshot_due, _, 0),
    forall(member(sync(T), Entries),
           catch(thread_send_message(T, oro_redis_synced), _, true)),
    length(Changes, Count),
    retract(published(P0)),
    P is P0 + Count,
    setting(snapshot_every, Every),
    (   P >= Every
    ->  assertz(published(0)),
        flag(oro_redis_snapshot_due, _, 1)
    ;   assertz(published(P))
    ).

sync_request(sync(_)).

%   snapshot_entries(+World, +Entries0, -Entries): a snapshot of every
%   shared model (of `world` too if World), taken under the store's
%   write lock together with the entries still queued, which it
%   replaces: the next entries are changes made after it.  The world
%   model is written by every node, so a node's snapshot of it is only
%   published when that node dropped some of its own changes.

snapshot_entries(World, Entries0, Entries) :-
    include(sync_request, Entries0, Syncs),
    with_mutex(oro_write, locked_snapshot(World, Snapshots, Queued)),
    include(sync_request, Queued, Syncs2),
    exclude(sync_request, Entries0, Changes0),
    exclude(sync_request, Queued, Changes1),
    append(Changes0, Changes1, Changes),
    include(world_change(World), Changes, WorldChanges),
    append([Snapshots, WorldChanges, Syncs, Syncs2], Entries).

world_change(false, change(world, _)).

locked_snapshot(World, Snapshots, Queued) :-
    oro_drain_queue(oro_redis_out, Queued),
    flag(oro_redis_dropped, Dropped, 0),
    (   Dropped > 0
    ->  print_message(informational, oro_redis(resync(Dropped)))
    ;   true
    ),
    config(share, Share),
    findall(snapshot(Model, Ops),
            ( member(Model, Share),
              (   Model == world
              ->  World == true
              ;   true
              ),
              model_triples(Model, Ops)
            ),
            Snapshots).

model_triples(Model, Ops) :-
    findall(a(Layer, S, P, O),
            ( oro_graph_layer(G, Model, Layer0),
              layer_key(Layer0, Layer),
              rdf(S, P, O, G)
            ),
            Ops).

xadd_command(Entry, xadd(Stream, maxlen, '~', Len, '*',
                         node, Node, kind, Kind, model, Model,
                         ops, Text) -> _Id) :-
    Entry =.. [Kind, Model, Ops],
    config(node, Node),
    entry_stream(Model, Stream),
    setting(stream_length, Len),
    format(string(Text), '~k', [Ops]).

entry_stream(world, 'oro:world') :- !.
entry_stream(_, Stream) :-
    config(node, Node),
    node_stream(Node, Stream).

node_stream(Node, Stream) :-
    atom_concat('oro:node:', Node, Stream).

%   snapshot_ids(+Conn, +Entries, +Commands): note under
%   oro:snapshot:STREAM the id of the last snapshot appended to each
%   stream, and this node in the set oro:nodes.

snapshot_ids(Conn, Entries, Commands) :-
    (   memberchk(snapshot(_, _), Entries)
    ->  config(node, Node),
        redis(Conn, sadd('oro:nodes', Node)),
        forall(nth1(I, Entries, snapshot(Model, _)),
               ( nth1(I, Commands, _ -> Id),
                 entry_stream(Model, Stream),
                 redis(Conn, set('oro:snapshot':Stream, Id))
               ))
    ;   true
    ).

		 /*******************************
		 *           FOLLOWER           *
		 *******************************/

follower :-
    follower_loop(none, 0.05).

follower_loop(Conn, _) :-
    \+ running,
    !,
    close_connection(Conn).
follower_loop(Conn0, Pause) :-
    (   catch(follow_once(Conn0, Conn), E, redis_failed(E, Conn0))
    ->  follower_loop(Conn, 0.05)
    ;   sleep(Pause),
        Pause1 is min(2, Pause*2),
        follower_loop(none, Pause1)
    ).

%   follow_once(+Conn0, -Conn): one XREAD of every followed stream.

follow_once(Conn0, Conn) :-
    connection(Conn0, Conn),
    followed_streams(Conn, Streams),
    (   Streams == []
    ->  sleep(0.2)
    ;   (   config(world, true),
            \+ oro_model(world)                % a reset wiped it
        ->  oro_create_model(world)
        ;   true
        ),
        maplist(lost_model, Streams),
        maplist(start_id(Conn), Streams, Ids),
        setting(batch, Batch),
        append(Streams, Ids, Args),
        Command =.. [xread, count, Batch, block, 1000, streams|Args],
        (   redis(Conn, Command, Reply)
        ->  forall(member([Stream, Entries], Reply),
                   apply_entries(Entries, Stream))
        ;   true                            % nothing new within 1 s
        )
    ).

followed_streams(Conn, Streams) :-
    config(node, Self),
    config(follow, Follow),
    (   Follow == (*)
    ->  redis(Conn, smembers('oro:nodes'), Members),
        maplist(to_atom, Members, Nodes0)
    ;   Nodes0 = Follow
    ),
    sort(Nodes0, Nodes1),
    exclude(==(Self), Nodes1, Nodes),
    maplist(node_stream, Nodes, NodeStreams),
    (   config(world, true)
    ->  Streams = ['oro:world'|NodeStreams]
    ;   Streams = NodeStreams
    ).

%   lost_model(+Stream): if the model Stream is applied to is gone (a
%   reset wiped the models), read Stream again from its last snapshot
%   (the world model, made again above, from the start of its stream).

lost_model(Stream) :-
    (   applied(Stream, _),
        stream_model(Stream, Model),
        \+ oro_model(Model)
    ->  retractall(applied(Stream, _)),
        debug(oro(redis), 'Model ~w gone: reading ~w again', [Model, Stream])
    ;   true
    ).

stream_model('oro:world', world) :- !.
stream_model(Stream, Node) :-
    atom_concat('oro:node:', Node, Stream).

to_atom(X, A) :-
    format(atom(A), '~w', [X]).

%   start_id(+Conn, +Stream, -Id): read Stream after Id: the last entry
%   applied, unless that is older than the stream's first entry (or
%   none was applied): then just before its last snapshot (or from the
%   start if it has none).

start_id(Conn, Stream, Id) :-
    (   applied(Stream, Last),
        \+ trimmed_past(Conn, Stream, Last)
    ->  Id = Last
    ;   redis(Conn, get('oro:snapshot':Stream), Snap0),
        to_atom(Snap0, Snap),
        \+ ( applied(Stream, Last),
             id_compare(>, Last, Snap)
           )
    ->  id_before(Snap, Id)
    ;   Id = '0'
    ).

trimmed_past(Conn, Stream, Last) :-
    redis(Conn, xrange(Stream, -, +, count, 1), [[First0, _]]),
    to_atom(First0, First),
    id_compare(<, Last, First),
    \+ id_before(First, Last).

id_parts(Id, Ms, Seq) :-
    split_string(Id, "-", "", [MsS, SeqS]),
    number_string(Ms, MsS),
    number_string(Seq, SeqS).

id_compare(Order, A, B) :-
    id_parts(A, MsA, SeqA),
    id_parts(B, MsB, SeqB),
    compare(Order, MsA-SeqA, MsB-SeqB).

id_before(Id, Before) :-
    id_parts(Id, Ms, Seq),
    (   Seq > 0
    ->  Seq1 is Seq - 1,
        format(atom(Before), '~d-~d', [Ms, Seq1])
    ;   Ms1 is Ms - 1,
        format(atom(Before), '~d-18446744073709551615', [Ms1])
    ).

%   apply_entries(+Entries, +Stream): apply the entries of one read of
%   Stream, in order, as one store transaction that also records the
%   id of the last (oro_persist_record/1): all of them are applied, or
%   none, and then read again from the same place next time (with a
%   warning).  A malformed entry is skipped, with a warning.  One
%   transaction a read rather than one an entry: with --db each
%   transaction is flushed to disk, and a node catching up reads up to
%   `batch` entries at a time.

apply_entries(Entries, Stream0) :-
    to_atom(Stream0, Stream),
    maplist(parse_entry(Stream), Entries, Parsed),
    last(Parsed, Last),
    arg(1, Last, LastId),
    (   catch(oro_store_write(redis_apply(Stream),
                              apply_parsed(Parsed, Stream, LastId)),
              E,
              ( print_message(warning, E),
                fail
              ))
    ->  retractall(applied(Stream, _)),
        assertz(applied(Stream, LastId)),
        debug(oro(redis), 'Applied ~w up to ~w', [Stream, LastId])
    ;   Parsed = [First|_],
        arg(1, First, FirstId),
        print_message(warning, oro_redis(not_applied(Stream, FirstId)))
    ).

%   parse_entry(+Stream, +Entry, -Parsed): entry(Id, Model, Kind, Ops),
%   or bad(Id).  The agent model of a node is created here, before the
%   transaction that applies its entries.

parse_entry(Stream, [Id0, Fields], Parsed) :-
    to_atom(Id0, Id),
    fields_pairs(Fields, Pairs),
    (   memberchk(kind-Kind, Pairs),
        memberchk(Kind, [change, snapshot]),
        memberchk(node-Node, Pairs),
        memberchk(ops-Text, Pairs),
        catch(term_string(Ops, Text), _, fail),
        is_list(Ops)
    ->  local_model(Stream, Node, Model),
        Parsed = entry(Id, Model, Kind, Ops)
    ;   print_message(warning, oro_redis(bad_entry(Stream, Id))),
        Parsed = bad(Id)
    ).

apply_parsed(Parsed, Stream, LastId) :-
    forall(member(entry(_, Model, Kind, Ops), Parsed),
           apply_ops(Kind, Model, Ops)),
    oro_persist_record(redis_applied(Stream, LastId)).

fields_pairs([], []).
fields_pairs([K0, V0|T], [K-V|Pairs]) :-
    to_atom(K0, K),
    to_atom(V0, V),
    fields_pairs(T, Pairs).

%   local_model(+Stream, +Entry, -Model): the model an entry goes in:
%   `world`, or the agent model named after the node that wrote it
%   (created if needed).

local_model('oro:world', _, world) :-
    !,
    oro_create_model(world).
local_model(_, Model, Model) :-
    (   oro_model(Model)
    ->  true
    ;   oro_create_agent(Model, Model)
    ).

apply_ops(snapshot, Model, Ops) :-
    apply_snapshot(Model, Ops).
apply_ops(change, Model, Ops) :-
    maplist(apply_op(Model), Ops).

apply_op(Model, a(Layer, S, P, O)) :-
    (   Layer == mask
    ->  oro_graph(Model, mask, G),
        rdf_assert(S, P, O, G)
    ;   Model == world,
        oro_functional_property(world, P)
    ->  replace_value(S, P, O),
        oro_store_assert(world, [rdf(S, P, O)], Layer)
    ;   oro_store_assert(Model, [rdf(S, P, O)], Layer)
    ).
apply_op(Model, r(Layer, S, P, O)) :-
    (   Layer == mask
    ->  oro_graph(Model, mask, G),
        rdf_retractall(S, P, O, G)
    ;   oro_store_forget(Model, Layer, [rdf(S, P, O)])
    ).

%   replace_value(+S, +P, +O): the functional property P of S in the
%   world model gets value O: its other values go.

replace_value(S, P, O) :-
    findall(rdf(S, P, Old),
            ( oro_asserted(world, S, P, Old),
              Old \== O
            ),
            Olds),
    (   Olds == []
    ->  true
    ;   oro_store_retract(world, Olds)
    ).

%   apply_snapshot(+Model, +Ops): make each graph of Model hold exactly
%   the triples of the snapshot (writing the difference only).

apply_snapshot(Model, Ops) :-
    findall(Layer-t(S, P, O), member(a(Layer, S, P, O), Ops), Pairs0),
    forall(oro_graph_layer(G, Model, Layer0),
           ( layer_key(Layer0, Layer),
             findall(t(S, P, O), member(Layer-t(S, P, O), Pairs0), New0),
             sort(New0, New),
             findall(t(S, P, O), rdf(S, P, O, G), Old0),
             sort(Old0, Old),
             ord_subtract(Old, New, Gone),
             ord_subtract(New, Old, Added),
             forall(member(t(S, P, O), Gone),
                    apply_op(Model, r(Layer, S, P, O))),
             forall(member(t(S, P, O), Added),
                    apply_op(Model, a(Layer, S, P, O)))
           )).

		 /*******************************
		 *        RESTART (--db)        *
		 *******************************/

%   restore_applied: the last entry applied from each stream, as the
%   commit log recorded it.

restore_applied :-
    retractall(applied(_, _)),
    oro_persist_records(Records),
    forall(member(redis_applied(Stream, Id), Records),
           ( retractall(applied(Stream, _)),
             assertz(applied(Stream, Id))
           )).

:- multifile oro_persist:live_records/1.

oro_persist:live_records(Records) :-
    findall(redis_applied(S, Id), applied(S, Id), Records).

		 /*******************************
		 *           MESSAGES           *
		 *******************************/

:- multifile prolog:message//1.

prolog:message(oro_redis(buffer_full(Max))) -->
    [ 'oro: Redis publishing buffer full (~D entries): changes are no \c
       longer queued; a snapshot of the shared models will be published \c
       once Redis is reachable'-[Max] ].
prolog:message(oro_redis(resync(N))) -->
    [ 'oro: Redis reachable again: ~D change(s) were dropped, a snapshot \c
       replaces them'-[N] ].
prolog:message(oro_redis(unreachable(E))) -->
    [ 'oro: Redis unreachable (retrying): ' ],
    translate(E).
prolog:message(oro_redis(reconnected(Host:Port))) -->
    [ 'oro: Redis at ~w:~w reachable again'-[Host, Port] ].
prolog:message(oro_redis(not_applied(Stream, Id))) -->
    [ 'oro: could not apply the entries of Redis stream ~w from ~w \c
       (read again next time)'-[Stream, Id] ].
prolog:message(oro_redis(bad_entry(Stream, Id))) -->
    [ 'oro: ignored a malformed entry ~w of Redis stream ~w'-[Id, Stream] ].

translate(E) -->
    { message_to_codes(E, Codes) },
    [ '~s'-[Codes] ].

message_to_codes(E, Codes) :-
    (   catch(message_to_codes_(E, Codes), _, fail)
    ->  true
    ;   format(codes(Codes), '~q', [E])
    ).

message_to_codes_(E, Codes) :-
    '$messages':translate_message(E, Lines, []),
    with_output_to(codes(Codes), print_message_lines(current_output, '', Lines)).
