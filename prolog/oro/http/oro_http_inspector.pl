:- module(oro_http_inspector,
          [ oro_inspector_overview/1,   % -Overview
            oro_inspector_models/1,     % -Models
            oro_inspector_classes/3,    % +Model, +Class, -Children
            oro_inspector_resource/3,   % +Model, +Resource, -Page
            oro_inspector_graph/4,      % +Model, +Resource, +Hops, -Graph
            oro_inspector_explain/3     % +Model, +Triple, -Why
          ]).
:- use_module(library(http/http_dispatch)).
:- use_module(library(http/http_parameters)).
:- use_module(library(http/http_json)).
:- use_module(library(semweb/rdf_db),
              [rdf_graph/1, rdf_graph_property/2, rdf_is_bnode/1,
               rdf_equal/2]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(aggregate)).
:- use_module(library(pairs)).
:- use_module(library(option)).
:- use_module(library(settings)).
:- use_module(library(debug)).
:- use_module(library(oro/oro_store), [oro_graph_layer/3, oro_model/1, oro_asserted/4,
                          oro_resolve_model/2, oro_store_read/1]).
:- use_module(library(oro/reason/oro_reason), [oro_holds/4]).
:- use_module(library(oro/questions/oro_taxonomy), [oro_direct_subclasses/3, oro_instances/3,
                             oro_classes_of/3,
                             oro_direct_classes_of/3]).
:- use_module(library(oro/questions/oro_lookup), [oro_lookup/3, oro_label/3, oro_exists/2]).
:- use_module(library(oro/oro_names), [oro_iri_name/2, oro_name_iri/2]).
:- use_module(library(oro/events/oro_events), [oro_watchers/2]).
:- use_module(library(oro/oro_memory), [oro_memory_deadlines/2]).
:- use_module(library(oro/questions/oro_explain), [oro_explain/3]).
:- use_module(library(oro/http/oro_http_feed)).

/** <module> The web inspector: what the robot believes, in a browser

Pages served by the HTTP side (oro_http) to look into a running oro,
read-only:

  - `/`: overview (models and their sizes per memory profile, socket
    connections, watchers, the next forgetting deadlines);
  - `/classes`: the class tree with instance counts, and a lookup box;
  - `/resource?iri=IRI&model=M`: labels, classes, asserted and inferred
    statements (each inferred one with a link to its explanation), the
    resource in each agent model;
  - `/graph?iri=IRI&model=M`: the resource's neighbourhood, a few hops;
  - `/feed`: the live feed of changes and events (oro_http_feed);
  - `/query`: SPARQL queries through `/sparql`, results as a table.

Every page is the same static shell (`web/inspector.html`, with its
own script and style sheet, no library and no network access beyond
the server); the script fetches the data as JSON from `/api/...`,
answered by the exported predicates of this module.  Each answer is
bounded (`max_rows`, `max_nodes`), so that a page stays fast on a large
store: a list cut short says how many there are.

Terms are JSON objects: `{"iri": IRI, "name": Short}` for a resource,
`{"literal": Text, "datatype": IRI}` or `{"literal": Text, "lang":
Tag}` for a literal.
*/

:- setting(max_rows, positive_integer, 100,
           'Statements (and other rows) listed at most per section').
:- setting(max_nodes, positive_integer, 60,
           'Resources drawn at most in a graph view').
:- setting(max_deadlines, positive_integer, 20,
           'Forgetting deadlines listed at most in the overview').
:- setting(max_watchers, positive_integer, 50,
           'Watchers listed at most in the overview').

:- multifile
    socket_connections/1.

%!  socket_connections(-Count) is semidet.
%
%   Multifile hook: Count is the number of ORO socket connections
%   being served (defined by the socket server).

:- http_handler(root(.), page, [id(inspector)]).
:- http_handler(root(classes), page, []).
:- http_handler(root(resource), page, []).
:- http_handler(root(graph), page, []).
:- http_handler(root(feed), page, []).
:- http_handler(root(query), page, []).
:- http_handler(root(web), web_file, [prefix]).
:- http_handler(root(api/overview), api_overview, []).
:- http_handler(root(api/models), api_models, []).
:- http_handler(root(api/classes), api_classes, []).
:- http_handler(root(api/lookup), api_lookup, []).
:- http_handler(root(api/resource), api_resource, []).
:- http_handler(root(api/graph), api_graph, []).
:- http_handler(root(api/explain), api_explain, []).

		 /*******************************
		 *        PAGES AND FILES       *
		 *******************************/

%   page(+Request): every page is the same shell; its script shows the
%   view its path names.

page(Request) :-
    web_path('inspector.html', Path),
    http_reply_file(Path, [unsafe(true), cache(false)], Request).

%   web_file(+Request): the script and style sheet of the pages.

web_file(Request) :-
    memberchk(path_info(Info), Request),
    atom_concat('/', Name, Info),
    memberchk(Name, ['inspector.js', 'inspector.css']),
    !,
    web_path(Name, Path),
    http_reply_file(Path, [unsafe(true), cache(false)], Request).
web_file(Request) :-
    http_404([], Request).

web_path(Name, Path) :-
    module_property(oro_http_inspector, file(File)),
    file_directory_name(File, Dir),
    atomic_list_concat([Dir, web, Name], /, Path).

		 /*******************************
		 *           JSON API           *
		 *******************************/

api_overview(Request) :-
    api(Request, [], [], oro_inspector_overview(Reply), Reply).

api_models(Request) :-
    api(Request, [], [], oro_inspector_models(Models), _{models:Models}).

api_classes(Request) :-
    api(Request, [class(C, [optional(true)])], [Model],
        ( default_class(C, Class),
          oro_inspector_classes(Model, Class, Children),
          term_json(Class, ClassJ)
        ),
        _{class:ClassJ, children:Children}).

api_lookup(Request) :-
    api(Request, [q(Text, [string])], [Model],
        lookup(Model, Text, Matches),
        _{matches:Matches}).

api_resource(Request) :-
    api(Request, [iri(R, [atom])], [Model],
        oro_inspector_resource(Model, R, Page), Page).

api_graph(Request) :-
    api(Request, [ iri(R, [atom]),
                   hops(Hops, [between(1, 3), default(2)])
                 ], [Model],
        oro_inspector_graph(Model, R, Hops, Graph), Graph).

api_explain(Request) :-
    api(Request, [ s(S, [atom]),
                   p(P, [atom]),
                   o(O0, [atom, optional(true)]),
                   lit(Lit, [string, optional(true)]),
                   datatype(DT, [atom, optional(true)]),
                   lang(Lang, [atom, optional(true)])
                 ], [Model],
        ( object_param(O0, Lit, DT, Lang, O),
          oro_inspector_explain(Model, rdf(S, P, O), Why)
        ),
        Why).

%   api(+Request, +Params, -ModelList, :Goal, -Reply): parse Params
%   (and `model`, default `myself`, bound in ModelList when asked),
%   run Goal in a read snapshot of the store and reply Reply as JSON.
%   Errors become a JSON object {"error": Message} with status 404
%   (unknown model or resource) or 400.

api(Request, Params, ModelList, Goal, Reply) :-
    catch(( http_parameters(Request,
                            [ model(Model0, [atom, default(myself)])
                            | Params
                            ]),
            (   ModelList = [Model]
            ->  oro_resolve_model(Model0, Model)
            ;   true
            ),
            oro_store_read(Goal)
          ),
          E, true),
    (   var(E)
    ->  reply_json_dict(Reply)
    ;   api_error(E)
    ).

api_error(E) :-
    (   E = error(existence_error(Type, _), _),
        memberchk(Type, [agent, resource])
    ->  Status = 404
    ;   Status = 400
    ),
    error_text(E, Message),
    debug(oro(http), 'Inspector API: ~w', [Message]),
    reply_json_dict(_{error:Message}, [status(Status)]).

%   error_text(+Error, -Text): the message Error prints, as a string.

error_text(E, Text) :-
    (   catch('$messages':translate_message(E, Lines, []), _, fail)
    ->  with_output_to(string(Text0),
                       print_message_lines(current_output, '', Lines)),
        split_string(Text0, "", " \n", [Text])
    ;   format(string(Text), '~q', [E])
    ).

default_class(C, Class) :-
    (   var(C)
    ->  rdf_equal(Class, owl:'Thing')
    ;   Class = C
    ).

object_param(O0, Lit, DT, Lang, O) :-
    (   nonvar(O0)
    ->  O = O0
    ;   var(Lit)
    ->  existence_error(parameter, o)
    ;   nonvar(Lang)
    ->  O = literal(lang(Lang, Lit))
    ;   nonvar(DT)
    ->  O = literal(type(DT, Lit))
    ;   O = literal(Lit)
    ).

		 /*******************************
		 *            OVERVIEW          *
		 *******************************/

%!  oro_inspector_overview(-Overview) is det.
%
%   Overview is a dict: `models`, one dict per model (`name`, `triples`
%   per memory profile, `total`, `watchers`); `connections`, the ORO
%   socket connections (`null` without a socket server); `watchers`,
%   the first `max_watchers` watchers of all models; `watcher_count`;
%   `deadlines`, the `max_deadlines` earliest pending forgetting
%   deadlines of all models, and `deadline_count`.

oro_inspector_overview(Overview) :-
    oro_inspector_models(Models),
    maplist(model_summary, Models, Summaries, WatcherLists),
    append(WatcherLists, Watchers0),
    length(Watchers0, WatcherCount),
    setting(max_watchers, MaxWatchers),
    take(MaxWatchers, Watchers0, Watchers),
    deadlines(Models, DeadlineCount, Deadlines),
    (   socket_connections(Connections)
    ->  true
    ;   Connections = null
    ),
    Overview = _{ models:Summaries,
                  connections:Connections,
                  watchers:Watchers,
                  watcher_count:WatcherCount,
                  deadlines:Deadlines,
                  deadline_count:DeadlineCount
                }.

%!  oro_inspector_models(-Models) is det.
%
%   Models are the names of the models, sorted.

oro_inspector_models(Models) :-
    findall(M, oro_model(M), Models0),
    sort(Models0, Models).

model_summary(Model, Summary, Watchers) :-
    findall(Profile-Count,
            ( oro_graph_layer(Graph, Model, profile(Profile)),
              graph_triples(Graph, Count)
            ), Pairs),
    dict_pairs(Profiles, _, Pairs),
    pairs_values(Pairs, Counts),
    sum_list(Counts, Total),
    oro_watchers(Model, Ws),
    length(Ws, NW),
    maplist(watcher_json(Model), Ws, Watchers),
    Summary = _{name:Model, triples:Profiles, total:Total, watchers:NW}.

graph_triples(Graph, Count) :-
    (   rdf_graph(Graph),
        rdf_graph_property(Graph, triples(Count0))
    ->  Count = Count0
    ;   Count = 0
    ).

watcher_json(Model, watcher(Id, Type, Trigger, Var, Patterns, N),
             _{id:IdT, model:Model, type:Type, trigger:TriggerT,
               var:VarT, patterns:PatternsT, subscribers:N}) :-
    maplist(format_text, [Id, Trigger, Var, Patterns],
            [IdT, TriggerT, VarT, PatternsT]).

format_text(Term, Text) :-
    format(string(Text), '~w', [Term]).

deadlines(Models, Count, Deadlines) :-
    findall(D-(Model-Triple-Profile),
            ( member(Model, Models),
              oro_memory_deadlines(Model, Ds),
              member(D-Triple-Profile, Ds)
            ), All),
    length(All, Count),
    keysort(All, Sorted),
    setting(max_deadlines, Max),
    take(Max, Sorted, First),
    maplist(deadline_json, First, Deadlines).

deadline_json(D-(Model-rdf(S, P, O)-Profile),
              _{at:D, model:Model, profile:Profile, statement:Triple}) :-
    triple_json(rdf(S, P, O), Triple).

%   take(+N, +List, -Prefix): the first N elements of List, or all.

take(N, List, Prefix) :-
    findall(X, limit(N, member(X, List)), Prefix).

		 /*******************************
		 *         CLASSES, LOOKUP      *
		 *******************************/

%!  oro_inspector_classes(+Model, +Class, -Children) is det.
%
%   Children are the direct subclasses of Class in Model (owl:Nothing
%   left out), sorted by name, at most `max_rows`, each a dict:
%   `class` (a term), `instances` (all of them, inferred included) and
%   `subclasses` (how many direct subclasses it has).  (The direct
%   instances are left out: counting them costs 25 times more.)

oro_inspector_classes(Model0, Class, Children) :-
    oro_resolve_model(Model0, Model),
    must_be(atom, Class),
    oro_direct_subclasses(Model, Class, Subs0),
    rdf_equal(Nothing, owl:'Nothing'),
    exclude(==(Nothing), Subs0, Subs1),
    map_list_to_pairs(oro_iri_name, Subs1, Keyed),
    keysort(Keyed, Sorted),
    pairs_values(Sorted, Subs2),
    setting(max_rows, Max),
    take(Max, Subs2, Subs),
    maplist(class_json(Model, Nothing), Subs, Children).

class_json(Model, Nothing, Class,
           _{class:ClassJ, instances:All, subclasses:NSub}) :-
    term_json(Class, ClassJ),
    oro_instances(Model, Class, Is),
    length(Is, All),
    oro_direct_subclasses(Model, Class, Subs),
    exclude(==(Nothing), Subs, Subs1),
    length(Subs1, NSub).

lookup(Model, Text, Matches) :-
    oro_lookup(Model, Text, Pairs),
    setting(max_rows, Max),
    take(Max, Pairs, First),
    findall(_{term:J, kind:Kind},
            ( member(R-Kind, First),
              term_json(R, J)
            ), Matches).

		 /*******************************
		 *           RESOURCE           *
		 *******************************/

%!  oro_inspector_resource(+Model, +Resource, -Page) is det.
%
%   Page is a dict describing Resource in Model: `resource` (a term),
%   `label`, `labels` (every rdfs:label), `classes` (direct) and
%   `all_classes`; `asserted` and `inferred`, the statements with
%   Resource as subject or object that are asserted in Model or only
%   inferred, at most `max_rows` each (`more` tells whether some were
%   left out); `models`, per model: whether Resource is known there, its
%   direct classes and the number of statements asserted about it.
%
%   @error existence_error(resource, Resource) if no model knows it.

oro_inspector_resource(Model0, R, Page) :-
    oro_resolve_model(Model0, Model),
    must_be(atom, R),
    oro_inspector_models(Models),
    (   member(M, [Model|Models]),
        oro_exists(M, R)
    ->  true
    ;   existence_error(resource, R)
    ),
    (   oro_exists(Model, R)
    ->  label(Model, R, Label),
        rdf_equal(Lbl, rdfs:label),
        findall(L, ( oro_holds(Model, R, Lbl, L0), term_json(L0, L) ), Labels),
        classes_of(Model, R, Direct, All),
        maplist(term_json, Direct, DirectJ),
        maplist(term_json, All, AllJ),
        statements(Model, R, asserted, Asserted, MoreA),
        statements(Model, R, inferred, Inferred, MoreI)
    ;   oro_iri_name(R, Label),
        maplist(=([]), [Labels, DirectJ, AllJ, Asserted, Inferred]),
        maplist(=(false), [MoreA, MoreI])
    ),
    maplist(model_view(R), Models, Views),
    term_json(R, RJ),
    Page = _{resource:RJ, model:Model, label:Label, labels:Labels,
             classes:DirectJ, all_classes:AllJ,
             asserted:Asserted, asserted_more:MoreA,
             inferred:Inferred, inferred_more:MoreI,
             models:Views}.

%   label(+Model, +R, -Label) and classes_of(+Model, +R, -Direct, -All)
%   for any resource: a class or property has no classes here.

label(Model, R, Label) :-
    catch(oro_label(Model, R, Label), error(existence_error(_, _), _),
          oro_iri_name(R, Label)).

classes_of(Model, R, Direct, All) :-
    catch(( oro_direct_classes_of(Model, R, Direct),
            oro_classes_of(Model, R, All)
          ), error(existence_error(_, _), _),
          ( Direct = [], All = [] )).

%   statements(+Model, +R, +Kind, -Triples, -More): at most max_rows
%   statements of Kind (asserted, inferred) about R, subject or object.

statements(Model, R, Kind, Triples, More) :-
    setting(max_rows, Max),
    Limit is Max + 1,
    findall(T, limit(Limit, distinct(T, statement(Kind, Model, R, T))), Ts),
    length(Ts, Len),
    (   Len > Max
    ->  More = true,
        take(Max, Ts, Kept)
    ;   More = false,
        Kept = Ts
    ),
    maplist(triple_json, Kept, Triples).

statement(Kind, Model, R, rdf(S, P, O)) :-
    (   S = R
    ;   O = R
    ),
    kind_holds(Kind, Model, S, P, O).

kind_holds(asserted, Model, S, P, O) :-
    oro_asserted(Model, S, P, O).
kind_holds(inferred, Model, S, P, O) :-
    oro_holds(Model, S, P, O),
    \+ oro_asserted(Model, S, P, O).

model_view(R, Model, _{model:Model, known:Known, classes:Classes,
                      statements:Count}) :-
    (   oro_exists(Model, R)
    ->  Known = true,
        classes_of(Model, R, Cs, _),
        maplist(term_json, Cs, Classes),
        aggregate_all(count, distinct(T, statement(asserted, Model, R, T)),
                      Count)
    ;   Known = false,
        Classes = [],
        Count = 0
    ).

%!  oro_inspector_explain(+Model, +Triple, -Why) is det.
%
%   Why is a dict telling why Triple (rdf(S, P, O)) holds in Model:
%   `statement`, `holds` (false if it does not), `facts` (each a dict
%   `statement`, `origin`) and `axioms`, from oro_explain/3;
%   `unexplained` is true for a derivation it cannot replay.

oro_inspector_explain(Model0, rdf(S, P, O), Why) :-
    oro_resolve_model(Model0, Model),
    triple_json(rdf(S, P, O), TJ),
    (   oro_explain(Model, rdf(S, P, O), E)
    ->  (   E = explanation(_, Facts, Axioms)
        ->  maplist(fact_json, Facts, FactsJ),
            maplist(triple_json, Axioms, AxiomsJ),
            Why = _{statement:TJ, holds:true, unexplained:false,
                    facts:FactsJ, axioms:AxiomsJ}
        ;   Why = _{statement:TJ, holds:true, unexplained:true,
                    facts:[], axioms:[]}
        )
    ;   Why = _{statement:TJ, holds:false, unexplained:false,
                facts:[], axioms:[]}
    ).

fact_json(fact(T, Origin), _{statement:TJ, origin:OriginT}) :-
    triple_json(T, TJ),
    format_text(Origin, OriginT).

		 /*******************************
		 *             GRAPH            *
		 *******************************/

%!  oro_inspector_graph(+Model, +Resource, +Hops, -Graph) is det.
%
%   Graph is the neighbourhood of Resource in Model, up to Hops links
%   away, following the statements asserted in Model between resources
%   (either way; classes are reached but not gone through): a dict with
%   `nodes` (`id`, `name`, `hops`, `kind`: `resource` or `class`) and
%   `edges` (`from`, `to`, `p`, `name`), at most `max_nodes` nodes.

oro_inspector_graph(Model0, R, Hops, Graph) :-
    oro_resolve_model(Model0, Model),
    must_be(atom, R),
    must_be(between(0, 5), Hops),
    setting(max_nodes, Max),
    rdf_equal(Type, rdf:type),
    bfs([R-0], Model, Hops, Max, Type, [R-0], Nodes, [], Edges0),
    sort(Edges0, Edges1),
    maplist(node_json(Model), Nodes, NodesJ),
    maplist(edge_json, Edges1, EdgesJ),
    Graph = _{root:R, nodes:NodesJ, edges:EdgesJ}.

bfs([], _, _, _, _, Seen, Nodes, Edges, Edges) :-
    reverse(Seen, Nodes).
bfs([N-D|Queue], Model, Hops, Max, Type, Seen0, Nodes, Edges0, Edges) :-
    (   D >= Hops
    ->  Next = [], Seen = Seen0, Edges1 = Edges0
    ;   D1 is D + 1,
        findall(edge(S, P, O), limit(200, link(Model, N, Type, S, P, O)), Links),
        foldl(visit(Max, D1), Links, Seen0-[]-Edges0, Seen-Next-Edges1)
    ),
    append(Queue, Next, Queue1),
    bfs(Queue1, Model, Hops, Max, Type, Seen, Nodes, Edges1, Edges).

link(Model, N, Type, N, P, O) :-
    \+ class_node(Model, N, Type),
    oro_asserted(Model, N, P, O),
    atom(O).
link(Model, N, Type, S, P, N) :-
    \+ class_node(Model, N, Type),
    oro_asserted(Model, S, P, N),
    P \== Type.

class_node(Model, N, Type) :-
    oro_asserted(Model, _, Type, N),
    !.

visit(Max, D, edge(S, P, O), Seen0-Next0-Edges0, Seen-Next-Edges) :-
    (   \+ memberchk(S-_, Seen0)
    ->  New = S
    ;   \+ memberchk(O-_, Seen0)
    ->  New = O
    ;   New = none
    ),
    length(Seen0, Len),
    (   New == none
    ->  Seen = Seen0, Next = Next0, Edges = [edge(S, P, O)|Edges0]
    ;   Len >= Max
    ->  Seen = Seen0, Next = Next0, Edges = Edges0
    ;   Seen = [New-D|Seen0],
        Next = [New-D|Next0],
        Edges = [edge(S, P, O)|Edges0]
    ).

node_json(Model, N-D, _{id:N, name:Name, hops:D, kind:Kind}) :-
    oro_iri_name(N, Name),
    rdf_equal(Type, rdf:type),
    (   class_node(Model, N, Type)
    ->  Kind = class
    ;   Kind = resource
    ).

edge_json(edge(S, P, O), _{from:S, to:O, p:P, name:Name}) :-
    oro_iri_name(P, Name).

		 /*******************************
		 *            TERMS             *
		 *******************************/

triple_json(rdf(S, P, O), _{s:SJ, p:PJ, o:OJ}) :-
    term_json(S, SJ),
    term_json(P, PJ),
    term_json(O, OJ).

term_json(literal(Lit), J) :-
    !,
    (   Lit = type(T, V)
    ->  format_text(V, Text),
        J = _{literal:Text, datatype:T}
    ;   Lit = lang(L, V)
    ->  format_text(V, Text),
        J = _{literal:Text, lang:L}
    ;   format_text(Lit, Text),
        J = _{literal:Text}
    ).
term_json(IRI, _{iri:IRI, name:Name}) :-
    oro_iri_name(IRI, Name).
